import init, { kli } from "./pkg/kli.js";

await init();
const path = kli([0, 0, 0, 1], [0.5, 0.5, 0.5, 0.5], { tolerance: 1e-5, step: 0.01 });
const q = path.quaternions;
const body = document.querySelector("#table tbody");
for (const t of [0, 0.2, 0.4, 0.55, 0.85, 1.2, 1.8, path.finalTime]) {
  const n = Math.round(t / 0.01);
  const row = body.insertRow();
  row.insertCell().textContent = t.toFixed(2);
  row.insertCell().textContent = Array.from(q.slice(4 * n, 4 * n + 4), (c) => c.toFixed(4)).join(", ");
}
document.querySelector("#status").textContent = `T = ${path.finalTime.toFixed(2)} (${path.steps} steps)`;
