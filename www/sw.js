// Offline support: every file the pages need is cached when first fetched; the network is tried
// first so a rebuilt page is never stale, and the cache answers when the server is gone. The file
// list and the cache name (a hash of those files) are written by `make www` from www/pages.js.
importScripts("pkg/build.js");
/** @type {{ cache: string, files: string[] }} */
const BUILD = self.KLI_BUILD;

self.addEventListener("install", (event) => {
  event.waitUntil(caches.open(BUILD.cache).then((cache) => cache.addAll(BUILD.files)).then(() => self.skipWaiting()));
});

// An older build's cache is dropped once this one runs.
self.addEventListener("activate", (event) => event.waitUntil(
  caches.keys()
    .then((names) => Promise.all(names.filter((name) => name.startsWith("kli-") && name !== BUILD.cache).map((name) => caches.delete(name))))
    .then(() => self.clients.claim()),
));

self.addEventListener("fetch", (event) => {
  const url = new URL(event.request.url);
  if (event.request.method !== "GET" || url.origin !== self.location.origin) return;
  event.respondWith(
    fetch(event.request)
      .then((response) => {
        const copy = response.clone();
        caches.open(BUILD.cache).then((cache) => cache.put(event.request, copy));
        return response;
      })
      .catch(() => caches.match(event.request, { ignoreSearch: true })),
  );
});
