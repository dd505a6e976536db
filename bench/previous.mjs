// The package as built from earlier commits, for the benchmarks to measure beside the current one
// in the same run (a speed figure means something only beside its reference). Each commit of
// bench/previous.json is checked out into a temporary worktree and built with its own Makefile
// (`make pkg`, or `make www` for its pages, using this checkout's node packages); its pkg/ or
// www/ is kept in target/previous/<commit>/, so a commit is built once (about 3 minutes on 2
// cores).
//   node bench/previous.mjs            builds what is missing, prints the directories
//   import { previous, load } from "./previous.mjs"   → [{ name, commit, dir }], an entry of one
import { execFileSync } from "node:child_process";
import { existsSync, mkdirSync, readFileSync, readdirSync, symlinkSync, writeFileSync, cpSync, rmSync } from "node:fs";
import { join } from "node:path";
import { serve } from "../scripts/static-server.mjs";

const root = new URL("../", import.meta.url).pathname;
/** The references: the last release (the first entry, which the targets compare against) and the one before it. */
export const REFERENCES = JSON.parse(readFileSync(join(root, "bench/previous.json"), "utf8"));

/** Builds `what` ("pkg", the npm package, or "www", the pages with their modules) at `commit`
 *  once, with the commit's own Makefile, and keeps it in target/previous/<commit>/<what>. */
function build(commit, what = "pkg") {
  const dir = join(root, "target/previous", commit);
  const kept = join(dir, what);
  if (existsSync(join(kept, what === "pkg" ? "kli.js" : "pkg/.built"))) return kept;
  const work = join(dir, "src");
  rmSync(work, { recursive: true, force: true });
  mkdirSync(dir, { recursive: true });
  execFileSync("git", ["worktree", "add", "--force", "--detach", work, commit], { cwd: root, stdio: "ignore" });
  try {
    // Its Makefile would `npm ci` without this stamp; this checkout's packages serve it, each
    // linked into a node_modules of its own (never this checkout's folder itself, which an
    // `npm ci` there would empty).
    const modules = join(work, "node_modules");
    mkdirSync(modules, { recursive: true });
    for (const name of readdirSync(join(root, "node_modules"))) {
      if (!name.startsWith(".")) symlinkSync(join(root, "node_modules", name), join(modules, name));
    }
    writeFileSync(join(modules, ".installed"), "");
    const env = { ...process.env, PATH: `${join(root, "node_modules/.bin")}:${process.env.PATH}` };
    console.error(`building ${what} at ${commit} (once; a few minutes)`);
    execFileSync("make", [what], { cwd: work, env, stdio: ["ignore", "ignore", "inherit"] });
    cpSync(join(work, what), kept, { recursive: true });
  } finally {
    execFileSync("git", ["worktree", "remove", "--force", work], { cwd: root, stdio: "ignore" });
  }
  return kept;
}

/** An entry (`kli`, `swarm`, `spline`) of the package in `dir`, initialised: its own module
 *  instance (the query string `tag` makes it a separate ES module beside this build's). */
export async function load(dir, entry, tag = dir) {
  const module = await import(`${dir}/${entry}.js?${tag}`);
  module.initSync({ module: readFileSync(join(dir, `${entry}_bg.wasm`)) });
  return module;
}

/** Every reference, built if need be: `{ name, commit, dir }`. */
export function previous() {
  return REFERENCES.map(({ name, commit }) => ({ name, commit, dir: build(commit) }));
}

/** The first reference (the previous release) with its pages built: `{ name, commit, www }`. */
export function previousPages() {
  const [{ name, commit }] = REFERENCES;
  return { name, commit, www: build(commit, "www") };
}

/** This checkout's pages and the previous release's (or those of `reference`, a `{ name,
 *  commit }`), each served: `{ release, builds, close }`, `builds` as `[label, origin, folder]`,
 *  ours first. */
export async function servePages(reference = REFERENCES[0]) {
  const release = { ...reference, www: build(reference.commit, "www") };
  const [ours, theirs] = [await serve(join(root, "www")), await serve(release.www)];
  const builds = [["ours", ours.origin, join(root, "www")], [`${release.name}, ${release.commit}`, theirs.origin, release.www]];
  return { release, builds, close: () => [ours, theirs].forEach((server) => server.close()) };
}

if (import.meta.url === `file://${process.argv[1]}`) {
  for (const { name, commit, dir } of previous()) console.log(`${name} (${commit}): ${dir}`);
}
