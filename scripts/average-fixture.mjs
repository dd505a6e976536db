// Writes tests/fixtures/average.json: bench/average_fixture.py's reference means (SciPy and a
// second implementation of the Karcher mean and the median), run in the bench's own Python
// environment (bench/python.mjs installs SciPy and NumPy there once). `make fixtures`.
import { writeFileSync } from "node:fs";
import { runPython } from "../bench/python.mjs";

const file = new URL("../tests/fixtures/average.json", import.meta.url);
writeFileSync(file, runPython("average_fixture.py", {}));
console.log(`wrote ${file.pathname}`);
