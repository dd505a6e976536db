// Writes the reference values the tests check against, computed without kli in the bench's own
// Python environment (bench/python.mjs installs its packages there once). `make fixtures`.
//   tests/fixtures/average.json  bench/average_fixture.py: SciPy's means, and a second
//                                implementation of the Karcher mean and the median
//   tests/fixtures/sync.json     bench/sync_fixture.py: GTSAM's chordal optima, NumPy's
//                                certificate eigenvalues
import { writeFileSync } from "node:fs";
import { runPython } from "../bench/python.mjs";

for (const [name, script] of [["average", "average_fixture.py"], ["sync", "sync_fixture.py"]]) {
  const file = new URL(`../tests/fixtures/${name}.json`, import.meta.url);
  writeFileSync(file, runPython(script, {}));
  console.log(`wrote ${file.pathname}`);
}
