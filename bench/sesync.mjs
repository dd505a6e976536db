// SE-Sync's own C++ (David Rosen's repository and its two submodules, Optimization and
// Preconditioners, from their git mirrors), built once into target/bench/sesync with Debian's
// Eigen, SuiteSparse and OpenBLAS (installed here when missing, as `make` installs Chromium),
// its example program replaced by bench/sesync_main.cpp. bench/poses.mjs runs it on each graph.
import { execFileSync, execSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, rmSync, copyFileSync, statSync } from "node:fs";
import { join } from "node:path";

const root = new URL("../", import.meta.url).pathname;
const dir = join(root, "target/bench/sesync");
const binary = join(dir, "build/bin/SE-Sync");
const runner = join(root, "bench/sesync_main.cpp");
const PACKAGES = ["cmake", "g++", "libeigen3-dev", "libsuitesparse-dev", "libopenblas-dev"];

/** The git directory of a mirror of `repo` (owner+name), or null. */
export function mirror(repo) {
  const base = `/work/.mirror/${repo}`;
  return [join(base, "repo"), base].find((d) => existsSync(join(d, "HEAD"))) ?? null;
}

/** A git tree (`HEAD` or a folder of it) exported into `into`. */
function exportTree(gitDir, into, tree = "HEAD") {
  mkdirSync(into, { recursive: true });
  execSync(`git --git-dir='${gitDir}' archive ${tree} | tar -x -C '${into}'`, { stdio: ["ignore", "ignore", "inherit"] });
}

/** `{ run(path), version }`, or `{ error }` saying why SE-Sync's C++ cannot be had here. */
export function seSync() {
  const gits = ["david-m-rosen+SE-Sync", "david-m-rosen+Optimization", "david-m-rosen+Preconditioners"].map(mirror);
  if (gits.some((g) => g === null)) return { error: "SE-Sync's mirrors (SE-Sync, Optimization, Preconditioners under /work/.mirror) are absent" };
  const version = execFileSync("git", ["--git-dir", gits[0], "rev-parse", "--short", "HEAD"], { encoding: "utf8" }).trim();
  const stale = !existsSync(binary) || statSync(binary).mtimeMs < statSync(runner).mtimeMs;
  if (stale) {
    try {
      const missing = PACKAGES.filter((p) => {
        try { execFileSync("dpkg", ["-s", p], { stdio: "ignore" }); return false; } catch { return true; }
      });
      if (missing.length) {
        console.log(`installing ${missing.join(", ")} for SE-Sync's C++ (once)`);
        execSync(`apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq ${missing.join(" ")} >/dev/null`, { stdio: "inherit" });
      }
      console.log(`building SE-Sync's C++ at ${version} into ${dir} (about a minute, once)`);
      rmSync(dir, { recursive: true, force: true });
      const src = join(dir, "src");
      mkdirSync(src, { recursive: true });
      exportTree(gits[0], join(src, "C++"), "HEAD:C++");
      for (const [k, name] of [[1, "Optimization"], [2, "Preconditioners"]]) {
        rmSync(join(src, "C++", name), { recursive: true, force: true });
        exportTree(gits[k], join(src, "C++", name));
      }
      copyFileSync(runner, join(src, "C++/examples/main.cpp"));
      const build = join(dir, "build");
      mkdirSync(build);
      // Release, with the machine's own instructions (SE-Sync's ENABLE_VECTORIZATION).
      execFileSync("cmake", [join(src, "C++"), "-DCMAKE_BUILD_TYPE=Release", "-DENABLE_VECTORIZATION=ON"], { cwd: build, stdio: "ignore" });
      execFileSync("make", ["-j2", "SE-Sync"], { cwd: build, stdio: "ignore" });
    } catch (e) {
      return { error: `SE-Sync's C++ did not build: ${e.message.split("\n")[0]}` };
    }
  }
  const out = join(dir, "result.json");
  return {
    version,
    /** SE-Sync on `path`: its time, status, rank, cost and poses (bench/sesync_main.cpp). */
    run(path) {
      execFileSync(binary, [path, out], { stdio: "ignore", timeout: 600_000, env: { ...process.env, OMP_NUM_THREADS: "1" } });
      return JSON.parse(readFileSync(out, "utf8"));
    },
  };
}
