// The bench's Python: a virtual environment of its own (target/bench-venv), made on first use
// with the versions below, so `make bench` installs what it needs itself: SciPy and NumPy, and
// the synchronisation anchors GTSAM, COLMAP (pycolmap) and Theia (pytheia).
import { execFileSync } from "node:child_process";
import { existsSync } from "node:fs";

const root = new URL("../", import.meta.url).pathname;
const venv = `${root}target/bench-venv`;
export const SCIPY = "1.17.1";
const PACKAGES = [`scipy==${SCIPY}`, "numpy==2.4.6", "gtsam==4.3.0", "pycolmap==4.2.1", "pytheia==1.2.1"];

/** The venv's python, made (about a minute, once) when missing or without a package. */
export function python() {
  const bin = `${venv}/bin/python`;
  const ready = () => {
    try {
      const check = ["-c", "import scipy, gtsam, pycolmap, pytheia; print(scipy.__version__)"];
      return execFileSync(bin, check, { encoding: "utf8", stdio: ["ignore", "pipe", "ignore"] }).trim();
    } catch {
      return null;
    }
  };
  if (!existsSync(bin)) execFileSync("python3", ["-m", "venv", venv], { stdio: "inherit" });
  if (ready() !== SCIPY) {
    console.log(`installing ${PACKAGES.join(", ")} into ${venv} (once)`);
    execFileSync(`${venv}/bin/pip`, ["install", "--quiet", "--disable-pip-version-check", ...PACKAGES], { stdio: "inherit" });
  }
  return bin;
}

/** Runs `script` (a path under bench/) with `input` as JSON on stdin; returns stdout's bytes. */
export function runPython(script, input) {
  return execFileSync(python(), [`${root}bench/${script}`], {
    input: JSON.stringify(input),
    maxBuffer: 1 << 30,
  });
}
