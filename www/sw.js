// Offline support: every file the page needs is cached when first fetched; the network is tried
// first so a rebuilt page is never stale, and the cache answers when the server is gone.
const CACHE = "kli-demo-v6";
const FILES = [
  "./", "index.html", "style.css", "main.js", "clock.js", "dom.js", "form.js", "input.js", "numbers.js",
  "presets.js", "summary.js", "url.js", "views.js", "canvases.js", "exports.js", "kli-figure.js", "swarm.html", "swarm.js", "keyframes.html", "keyframes.js", "pkg/kli_demo.js", "pkg/kli_demo_bg.wasm",
  "pkg/swarm_demo.js", "pkg/swarm_demo_bg.wasm", "pkg/spline_demo.js", "pkg/spline_demo_bg.wasm",
];

self.addEventListener("install", (event) => {
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(FILES)).then(() => self.skipWaiting()));
});

self.addEventListener("activate", (event) => event.waitUntil(self.clients.claim()));

self.addEventListener("fetch", (event) => {
  const url = new URL(event.request.url);
  if (event.request.method !== "GET" || url.origin !== self.location.origin) return;
  event.respondWith(
    fetch(event.request)
      .then((response) => {
        const copy = response.clone();
        caches.open(CACHE).then((cache) => cache.put(event.request, copy));
        return response;
      })
      .catch(() => caches.match(event.request, { ignoreSearch: true })),
  );
});
