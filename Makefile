# Every target installs what it needs that is missing, so `make demo` and `make test` work on a
# fresh machine (see README, Quick start). Installs are skipped when already in place.
SHELL := /bin/bash
.SHELLFLAGS := -eu -o pipefail -c
.DEFAULT_GOAL := help

TARGET := wasm32-unknown-unknown
PORT ?= 8080
CARGO_BIN := $(HOME)/.cargo/bin
export PATH := $(CURDIR)/node_modules/.bin:$(CARGO_BIN):$(PATH)
# The wasm-bindgen CLI must be exactly the version the crate is pinned to (Cargo.lock).
WASM_BINDGEN_VERSION = $(shell awk '/^name = "wasm-bindgen"$$/ {getline; gsub(/version = |"/, ""); print}' Cargo.lock)
# wasm-opt: -O3 for the npm package's entries, whose sizes have a budget (at -O2 kli/swarm,
# kli/average and kli were 1.1–1.6% larger gzipped); -O2 for the pages'
# modules, where -O3 took 60–70% longer on the largest (the tour's 12.3 s against 7.4 s, kli/sync's
# 23.7 s against 14.1 s, binaryen's npm build here) for sizes within 0.5% either way and speeds
# the bench cannot tell apart (synchronizePoses on sphere2500 and city10000, the batch calls on
# 10⁵ pairs: docs/performance.md).
PKG_WASM_OPT := wasm-opt -O3
PAGE_WASM_OPT := wasm-opt -O2
# Features the Rust wasm32 target emits; wasm-opt must accept them.
WASM_FEATURES := --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
                 --enable-mutable-globals --enable-reference-types --enable-multivalue --enable-simd
# The release builds of the package's entries and the pages' modules: one target directory for
# all (cargo keeps each feature set's artifacts apart; the dependencies they share, wasm-bindgen's
# macros above all, are built once: the entries' builds took 145 s cold in five directories, 87 s
# in one), each bound right after its build, before the next overwrites the .wasm.
BUILDS := target/builds

.PHONY: mutants fixtures help setup setup-rust fmt-check clippy-canary setup-node setup-browser pkg www single demo serve test lint lint-rust lint-js \
        publish-check test-native test-wasm-node lint-wasm-portable test-wasm-browser test-package test-page \
        test-page-early test-page-late test-page-rest \
        lane-rust lane-web bench clean

help:
	@echo "make demo   build and serve the demo page at http://127.0.0.1:$(PORT)/"
	@echo "make test   run every check and test (lint, native, wasm under Node, package, Chromium)"
	@echo "make pkg    build the npm package into pkg/"
	@echo "make www    build the page's module into www/pkg/"
	@echo "make single each page as one self-contained HTML file in dist/single/ (works from file://)"
	@echo "make bench  run the benchmarks"
	@echo "make mutants   mutation testing of the core crate (long; MUTANTS_ARGS=\"-f FILE\" for one file)"
	@echo "make fixtures  recompute the reference values from SciPy and GTSAM (tests/fixtures)"

# The three at once: a fresh machine's wasm-bindgen build (CPU), apt's and npm's downloads.
setup:
	$(MAKE) --no-print-directory -j3 setup-rust setup-node setup-browser

setup-rust:
	@rustup target list --installed | grep -qx $(TARGET) || rustup target add $(TARGET)
	@rustup component list --installed | grep -q '^clippy' || rustup component add clippy
	@rustup component list --installed | grep -q '^rustfmt' || rustup component add rustfmt
	@if [ "$$(wasm-bindgen --version 2>/dev/null)" != "wasm-bindgen $(WASM_BINDGEN_VERSION)" ]; then \
	  echo "installing wasm-bindgen-cli $(WASM_BINDGEN_VERSION) (about 2.5 minutes, once)"; \
	  cargo install wasm-bindgen-cli --version $(WASM_BINDGEN_VERSION); \
	fi

# node_modules is reinstalled whenever package-lock.json is newer than it.
setup-node: node_modules/.installed
node_modules/.installed: package.json package-lock.json
	npm ci --no-audit --no-fund
	@touch $@

# Chromium for the pages (the benchmarks), its driver for the wasm tests in a browser, and its
# headless shell for the end-to-end files (scripts/static-server.mjs, TEST_CHROMIUM).
setup-browser:
	@if ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null || ! command -v chromium-headless-shell >/dev/null; then \
	  echo "installing Debian's chromium, chromium-driver and chromium-headless-shell (about a minute, once)"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver chromium-headless-shell >/dev/null; \
	fi

# The npm package: crates/kli-wasm, the JavaScript API only, in entries with a module each:
# `kli` (kli.js, the default features), `kli/swarm` (swarm.js), `kli/spline` (spline.js),
# `kli/average` (average.js) and `kli/sync` (sync.js), each built with its feature alone (in BUILDS, where cargo keeps each
# feature set's artifacts, so every build stays cached).
ENTRIES := swarm spline average sync
# What each build reads: a build runs again only when one of these is newer than its stamp, so
# `make demo` serves at once when nothing changed (tests/e2e/contract.test.mjs checks it).
CORE_SOURCES := Cargo.toml Cargo.lock $(shell find src -name '*.rs')
PKG_SOURCES := $(CORE_SOURCES) crates/kli-wasm/Cargo.toml $(shell find crates/kli-wasm/src -name '*.rs') \
               $(wildcard crates/kli-wasm/js/*) \
               scripts/package-json.mjs scripts/glue.mjs
WWW_SOURCES := $(PKG_SOURCES) crates/kli-demo/Cargo.toml $(shell find crates/kli-demo/src -name '*.rs') \
               scripts/pages.mjs www/pages.js node_modules/.installed
pkg: setup-rust setup-node pkg/.built
	@cmp -s README.md pkg/README.md || cp README.md pkg/
pkg/.built: $(PKG_SOURCES)
	rm -rf pkg
	cargo build --release -p kli-wasm --lib --target $(TARGET) --target-dir $(BUILDS)
	wasm-bindgen --target web --out-dir pkg --out-name kli $(BUILDS)/$(TARGET)/release/kli_wasm.wasm
	for entry in $(ENTRIES); do \
	  cargo build --release -p kli-wasm --lib --target $(TARGET) --target-dir $(BUILDS) \
	    --no-default-features --features $$entry,small-allocator; \
	  wasm-bindgen --target web --out-dir pkg --out-name $$entry $(BUILDS)/$(TARGET)/release/kli_wasm.wasm; \
	done
	node scripts/glue.mjs pkg/kli.js $(foreach entry,$(ENTRIES),pkg/$(entry).js)
	@# Two at a time: wasm-opt (binaryen's npm build) keeps one core busy.
	printf '%s\n' kli $(ENTRIES) | xargs -P 2 -I '{}' $(PKG_WASM_OPT) $(WASM_FEATURES) pkg/{}_bg.wasm -o pkg/{}_bg.wasm
	@# kli/three and kli/gltf: plain JavaScript over kli/spline (resample.js shared).
	cp crates/kli-wasm/js/*.js crates/kli-wasm/js/*.d.ts pkg/
	cp README.md pkg/
	node scripts/package-json.mjs
	@for module in kli $(ENTRIES); do \
	  echo "pkg/$${module}_bg.wasm: $$(stat -c %s pkg/$${module}_bg.wasm) bytes, $$(gzip -9c pkg/$${module}_bg.wasm | wc -c) gzipped"; \
	done
	@touch $@

# The site: the pages' modules, the video codecs, and what the examples import, each a step of
# its own with its own stamp; then scripts/pages.mjs writes the pages' bundles, modulepreload
# links and the service worker's file list and cache name (a content hash).
PAGES := $(shell node scripts/pages.mjs names)
www: setup-rust setup-node pkg www/pkg/.built www/pkg/first/.built www/vendor/codecs.js www/examples/vendor/.built
	node scripts/pages.mjs write

# Each page's first picture, drawn by its module in Node at the size of each canvas in each
# layout (www/first-pictures.json; `node scripts/first-pictures.mjs --measure` after a change of
# the pages' layout), shown by the HTML before any script runs.
www/pkg/first/.built: www/pkg/.built www/first-pictures.json scripts/first-pictures.mjs www/pages.js $(wildcard www/*/state.js) $(wildcard www/*/page.html)
	node scripts/first-pictures.mjs
	@touch $@

# The pages' modules, one a page (the pages are listed in www/pages.js, the registry): a build of
# crates/kli-demo with the page's feature `<page>-page`, bound to www/pkg/<page>_demo.js, in the
# entries' target directory (BUILDS: faer, which the synchronisation page needs, is built there).
www/pkg/.built: $(WWW_SOURCES) pkg/.built
	@test -n "$(PAGES)" || { echo "no pages: node scripts/pages.mjs names printed nothing"; exit 1; }
	rm -rf www/pkg
	for page in $(PAGES); do \
	  cargo build --release -p kli-demo --lib --target $(TARGET) --target-dir $(BUILDS) --no-default-features --features $$page-page; \
	  wasm-bindgen --target web --out-dir www/pkg --out-name $${page}_demo $(BUILDS)/$(TARGET)/release/kli_demo.wasm; \
	  node scripts/glue.mjs www/pkg/$${page}_demo.js; \
	done
	printf '%s\n' $(PAGES) | xargs -P 2 -I '{}' $(PAGE_WASM_OPT) $(WASM_FEATURES) www/pkg/{}_demo_bg.wasm -o www/pkg/{}_demo_bg.wasm
	@for page in $(PAGES); do \
	  echo "www/pkg/$${page}_demo_bg.wasm: $$(stat -c %s www/pkg/$${page}_demo_bg.wasm) bytes, $$(gzip -9c www/pkg/$${page}_demo_bg.wasm | wc -c) gzipped"; \
	done
	@touch $@

# Saving a video (www/runtime/video/): mediabunny and gifenc, tree-shaken into one module, loaded only
# when a video is saved.
www/vendor/codecs.js: www/runtime/video/codecs.js node_modules/.installed
	esbuild www/runtime/video/codecs.js --bundle --format=esm --minify --log-level=warning '--banner:js=// @ts-nocheck' \
	  --outfile=$@

# What the examples import by name through their import map, served locally: the package's
# kli, kli/spline, kli/average and kli/three (which imports both); three.js as one minified
# module with its source map, as an app's bundler would serve it; reveal.js and its speaker-notes
# plugin for the example deck (examples/slides.html).
www/examples/vendor/.built: pkg/.built node_modules/.installed
	rm -rf www/examples/vendor
	mkdir -p www/examples/vendor/kli www/examples/vendor/three www/examples/vendor/reveal/theme
	cp pkg/kli.js pkg/kli_bg.wasm pkg/spline.js pkg/spline_bg.wasm pkg/average.js pkg/average_bg.wasm pkg/three.js pkg/resample.js \
	  www/examples/vendor/kli/
	esbuild node_modules/three/build/three.module.js --bundle --format=esm --minify --sourcemap \
	  --log-level=warning --outfile=www/examples/vendor/three/three.module.js
	cp node_modules/reveal.js/dist/reveal.mjs www/examples/vendor/reveal/reveal.module.js
	cp node_modules/reveal.js/dist/plugin/notes.mjs www/examples/vendor/reveal/notes.module.js
	cp node_modules/reveal.js/dist/reveal.css www/examples/vendor/reveal/
	cp node_modules/reveal.js/dist/theme/white.css www/examples/vendor/reveal/theme/
	@touch $@

# Each page as one self-contained HTML file (scripts, style sheet and .wasm inlined) that works
# opened from file:// with no server and no network: dist/single/<page>.html for every page;
# then the teacher's kit, those pages and the tour's figures as SVG in one zip the site serves
# (www/kli-teaching-kit.zip, linked from teach.html).
single: www
	node scripts/single.mjs
	node scripts/kit.mjs

demo: single
	@echo "Serving the demo at http://127.0.0.1:$(PORT)/  (Ctrl-C to stop)"
	python3 -m http.server $(PORT) --bind 127.0.0.1 --directory www

# Every step of `lint` and the tests, in three phases (docs/testing.md has the times). On two
# cores one step at a time left a core idle for long stretches (the release builds' LTO and
# codegen-units = 1, wasm-opt, tests that run on one thread), so the middle phase runs two lanes
# at once, each one step at a time, in target directories of their own (cargo locks a target
# directory, so two lanes in one would wait for each other):
#   setup      the installs, all three at once (a fresh machine's wasm-bindgen build, apt and npm)
#   lane-rust  fmt, clippy (the portable lanes' build too), rustdoc, and the Rust tests (target/)
#   lane-web   the release builds (pkg, www, single: target/builds), the packages' dry runs, tsc,
#              and the npm package's tests (tests/js)
#              and, once the site is built, the end-to-end files that assert nothing about
#              time (E2E_EARLY), one at a time beside the Rust lane's tests, which the web
#              lane would otherwise wait for; then, one at a time, as many of the other
#              files as start before the Rust lane ends (E2E_FLEX)
#   and, once its own steps pass, the Rust lane takes the end-to-end files no lane has begun,
#              four at a time, beside the web lane's last (test-page-rest)
#   test-page-late  any end-to-end files still left (none, unless the Rust lane ended before the
#              site was built), four at a time
# Each lane's lines are prefixed with its name. A failing step stops its lane and `make test`
# fails once the other lane is done (`cargo fmt --check` runs before both, to fail at once).
# One make runs the three installs at once (-j3, as `setup`: a fresh machine's wasm-bindgen build
# beside apt's and npm's downloads) and starts each lane as soon as what it needs is in place: the
# Rust lane once Rust's tools are and the formatting is checked, without waiting for npm ci (8 s
# of every CI run, the machine a third idle), the web lane once all three are. (The Rust lane
# needs Chromium only for test-wasm-browser, minutes later; apt has long finished by then.)
test:
	@rm -rf $(E2E_CLAIMS) $(E2E_READY) $(RUST_RUNNING)
	$(MAKE) --no-print-directory -j3 lane-rust lane-web
	@# Only when a file is left: test-page-late's prerequisites write the one-file pages and the
	@# kit again (2.5 s at the end of every run, the rest of the machine idle).
	@if [ -n "$$($(UNCLAIMED))" ]; then $(MAKE) --no-print-directory test-page-late E2E_SKIP_RAN=1; fi

# RUST_RUNNING exists while the Rust lane runs its steps: the web lane's end-to-end files read it.
# Then, where the site is built (E2E_READY), the Rust lane runs the end-to-end files left
# (test-page-rest) at once, beside the web lane's last file, rather than after it: with the site
# done, the web lane ran one file at a time past the Rust lane's end, the machine half idle until
# it ended (a 27 s file began 9 s before that end; 22 s at 50% or so, 2026-11-28).
lane-rust: fmt-check
	@mkdir -p target && touch $(RUST_RUNNING)
	@status=0; $(MAKE) --no-print-directory -j1 lint-rust lint-wasm-portable test-native test-wasm-node test-wasm-browser 2>&1 \
	  | sed -u 's/^/[rust] /' || status=$$?; rm -f $(RUST_RUNNING); \
	if [ $$status -eq 0 ] && [ -e $(E2E_READY) ]; then \
	  $(MAKE) --no-print-directory test-page-rest 2>&1 | sed -u 's/^/[rust] /' || status=$$?; \
	fi; exit $$status
lane-web: fmt-check setup-node setup-browser
	$(MAKE) --no-print-directory -j1 pkg www publish-check lint-js test-package single test-page-early E2E_FILL=1 2>&1 \
	  | sed -u 's/^/[web] /'

# Formatting, clippy (native and wasm32), rustdoc, and the page's JavaScript against the
# generated types: all without warnings; and both packages as they would be published.
lint: lint-rust lint-wasm-portable lint-js publish-check

# rustdoc over the whole workspace, kli-bench (one documented function) and the examples too:
# with them the dependencies resolve to the features the first clippy resolved (dev-dependencies
# and nalgebra's included), so rustdoc reuses clippy's checks of them. Over the libraries alone
# num-traits' features differed and faer with its 17 dependencies were checked once more (83 s
# of `lint` here).
# On wasm32 the workspace's crates are linted as the wasm tests build them (WASM_CLIPPY, below);
# here each entry's features alone (api is `kli`'s), which no test build has. Natively: kli-wasm's
# only code for wasm32 alone is its allocator, which these builds leave out, so the lints see the
# same code, and with kli-rotations selected too (its dev-dependencies, proptest's bitflags
# `std` above all) the dependencies resolve as in the first clippy and are not checked again.
# For wasm32 they were checked for these runs alone, faer for sync's: after the first clippy, on
# a quiet machine, 46 s and 67 core-seconds against 12 s and 19 (2026-11-28).
LINT_ENTRIES := api $(ENTRIES)
fmt-check: setup-rust
	cargo fmt --all --check
lint-rust: fmt-check
	cargo clippy --workspace --all-targets --all-features -- -D warnings
	for entry in $(LINT_ENTRIES); do \
	  cargo clippy -p kli-rotations -p kli-wasm --all-targets --no-default-features --features kli-wasm/$$entry -- -D warnings; \
	done
	RUSTDOCFLAGS="-D warnings" cargo doc --workspace --no-deps --all-features --lib --examples

lint-js: www
	tsc -p www/jsconfig.json

# The Rust crate and the npm package, packed and checked as `cargo publish` and `npm publish`
# would, without publishing (--allow-dirty: a working tree with changes may be checked too).
# The crate's verification builds it from its packaged copy without its default feature `sync`:
# with it, the build of faer that verification makes (its features resolved apart from the
# workspace's, so shared with no other build) took 74 s of a fresh machine's 15 minutes. That
# the packaged copy holds every file of src/, sync's too, is checked from the package's list.
# In BUILDS, the web lane's target directory: in target/ its verification waited for the Rust
# lane's lock on it (3 minutes, while `cargo test` built).
publish-check: pkg
	cargo publish --dry-run --allow-dirty --quiet --no-default-features -p kli-rotations --target-dir $(BUILDS)
	@cargo package --list --allow-dirty --quiet -p kli-rotations --target-dir $(BUILDS) | grep '^src/' | sort > target/packaged-src.txt
	@git ls-files src | sort | diff - target/packaged-src.txt || { echo "files of src/ missing from the crate's package (Cargo.toml's include)"; exit 1; }
	cd pkg && npm publish --dry-run --loglevel=error

# Without kli-bench: it has no tests (clippy checks it, `make bench` runs it), and building it
# for tests builds criterion and nalgebra once more.
test-native:
	cargo test --workspace --exclude kli-bench

# Clippy on wasm32 rides on the wasm test builds: clippy-driver compiles the workspace's crates
# in them (kli-rotations, kli-wasm with every feature, its tests, kli-demo and its tests), as
# `cargo clippy` runs it: RUSTC_WORKSPACE_WRAPPER, its flags in CLIPPY_ARGS with
# `__CLIPPY_HACKERY__` after each (cargo-clippy's own way of handing them over). A separate
# `cargo clippy --target wasm32` checked every dependency for wasm32 once more (faer, web-sys:
# 110 s of the Rust lane on CI). The canary fails the build if a lint no longer fails the driver
# this way (a warning would then pass unseen). kli-rotations' own tests are native-only.
# Each crate's wasm tests are one integration binary (kli-wasm's tests/wasm.rs, kli-demo's
# tests/browser.rs), named with `--test`: like `--tests`, it leaves out the doctests and plain
# `#[test]`s that wasm would report as passed without running them, and it builds no library test
# harness, which on wasm holds only native tests (the lib's `#[test]`s, run by test-native) and
# ran nothing: the two harnesses' builds and bindings cost 9–10 core-seconds (their cfg(test)
# code is linted natively, by lint-rust's `--all-targets`).
CLIPPY_DRIVER = $(shell rustup which clippy-driver 2>/dev/null || command -v clippy-driver)
WASM_CLIPPY = RUSTC_WORKSPACE_WRAPPER=$(CLIPPY_DRIVER) CLIPPY_ARGS=-D__CLIPPY_HACKERY__warnings__CLIPPY_HACKERY__
clippy-canary: setup-rust
	@mkdir -p target
	@printf 'pub fn empty(v: &[u8]) -> bool { v.len() == 0 }\n' > target/clippy-canary.rs
	@if $(WASM_CLIPPY) $(CLIPPY_DRIVER) rustc --edition 2021 --crate-type lib --emit metadata \
	  --out-dir target target/clippy-canary.rs 2>/dev/null; then \
	  echo "clippy-driver passed a lint with CLIPPY_ARGS=-D warnings: the wasm builds would not be linted"; exit 1; \
	fi

test-wasm-node: setup-rust clippy-canary
	WASM_BINDGEN_TEST_ONLY_NODE=1 $(WASM_CLIPPY) cargo test -p kli-wasm --all-features --target $(TARGET) --test wasm

# The build without simd128 (the plain [f64; 2] lanes, for engines without wasm SIMD), linted for
# wasm32, tests included: it builds and stays warning-free. The lanes are kli-rotations' (src/lanes.rs,
# its only code that simd128 changes; kli-wasm has none), so kli-rotations alone, whose one
# dependency here is glam: with kli-wasm and its entries' features, wasm-bindgen, js-sys and the
# host's macros were checked again for these flags alone (after the first clippy, 15.6 s and 27.9
# core-seconds against 2.1 s and 2.6, 2026-11-28). What it computes is checked natively, where
# the plain lanes are under test too: each of their operations bit for bit against the same one on
# each f64 (src/lanes.rs), and the batch kernels, one source generic over the lanes, give the
# same bits on them as on the lanes in use (src/batch/fast.rs). Running the whole wasm suite on
# them once more took 105–169 s of `make test`.
# Without `sync`, which uses no lanes and would check faer once more.
lint-wasm-portable: setup-rust
	CARGO_TARGET_WASM32_UNKNOWN_UNKNOWN_RUSTFLAGS="-C target-feature=-simd128" \
	cargo clippy -p kli-rotations --all-targets --no-default-features --target $(TARGET) -- -D warnings

test-wasm-browser: setup-rust setup-browser clippy-canary
	WASM_BINDGEN_TEST_ONLY_WEB=1 $(WASM_CLIPPY) cargo test -p kli-demo --target $(TARGET) --test browser

test-package: pkg
	node --test tests/js/

# What `make test` runs in the web lane as soon as the site is built, while the Rust lane's tests
# still run: files that time nothing (bundlers, the one-file pages, the links, the screenshots, the
# tour in Bosnian, the teacher's kit), so the load beside them changes no answer, only how long.
# As many as end with the Rust lane, no more: the suite is bound by its CPU, and with the hostile
# URLs here too the Rust lane, the longer, ended 130 s later (834 s against 705 s) for 42 s saved
# after it.
E2E_EARLY := $(addprefix tests/e2e/,bundlers.test.mjs single.test.mjs links.test.mjs look.test.mjs learn-lang.test.mjs teach.test.mjs)
E2E_LATE := $(filter-out $(E2E_EARLY),$(wildcard tests/e2e/*.test.mjs))
# After E2E_EARLY, the web lane of `make test` used to wait for the Rust lane (100 s on a fresh
# clone, 2026-11-28, a third of a core idle while the Rust lane ran its tests on one thread or
# two): it now takes the other files one at a time, for as long as the Rust lane runs
# (RUST_RUNNING), each claimed first in E2E_CLAIMS (a directory made for it: mkdir is atomic, so
# of two lanes one gets a file); the Rust lane then runs those left (test-page-rest), and
# `test-page-late` after the lanes any still unclaimed.
# The longer first (their times alone, in the headless shell: 32 s down to 3 s), so that the one
# still running when the Rust lane ends is a short one: the machine is half idle until it ends
# (smaller first, fuzz.test.mjs, 35 s, began 16 s before the Rust lane's end, and the machine
# stayed 37–71% busy for the 20 s until it ended). How many fit depends on the machine: on a slow
# one the Rust lane ends first and none run here.
E2E_FLEX := $(addprefix tests/e2e/,page.test.mjs fuzz.test.mjs contract.test.mjs \
              first-picture.test.mjs learn.test.mjs poses.test.mjs sync.test.mjs hostile-load.test.mjs swarm.test.mjs video.test.mjs \
              keyframes.test.mjs slides.test.mjs embed.test.mjs average.test.mjs exports.test.mjs examples.test.mjs)
ifneq ($(sort $(E2E_FLEX)),$(sort $(E2E_LATE)))
$(error E2E_FLEX must list every end-to-end file not in E2E_EARLY: $(filter-out $(E2E_FLEX),$(E2E_LATE)) missing)
endif
RUST_RUNNING := target/lane-rust.running
E2E_READY := target/e2e-ready
E2E_CLAIMS := target/e2e-claims
# Claims the end-to-end file $$file for the lane that runs it: true for one lane only.
CLAIM_FILE = { mkdir -p $(E2E_CLAIMS); mkdir $(E2E_CLAIMS)/$$(basename $$file) 2>/dev/null; }
# The files of E2E_FLEX not yet claimed, each claimed as it is printed.
CLAIM = for file in $(E2E_FLEX); do if $(CLAIM_FILE); then echo $$file; fi; done
# The same files, left unclaimed.
UNCLAIMED = for file in $(E2E_FLEX); do [ -d $(E2E_CLAIMS)/$$(basename $$file) ] || echo $$file; done
# Runs the end-to-end files in $$files (none: nothing), four at a time (test-page-late says why).
RUN_FOUR = if [ -n "$$files" ]; then node --test --test-concurrency=4 $$files; fi
test-page: test-page-early test-page-late
test-page-early: pkg www single setup-browser
	@$(if $(E2E_FILL),touch $(E2E_READY))
	node --test --test-concurrency=1 $(E2E_EARLY)
	@for file in $(if $(E2E_FILL),$(E2E_FLEX)); do \
	  [ -e $(RUST_RUNNING) ] || break; \
	  $(CLAIM_FILE) || continue; \
	  echo "the Rust lane still runs: $$file now"; \
	  node --test $$file; \
	done
# Run by the Rust lane of `make test` once its steps pass and the web lane has built the site:
# the end-to-end files no lane has claimed, four at a time (as test-page-late).
test-page-rest:
	@files=$$($(CLAIM)); \
	if [ -n "$$files" ]; then echo "the Rust lane is done: "$$files; fi; \
	$(RUN_FOUR)
# The other files four at a time (Node 20's runner takes one at a time on 2 cores:
# os.availableParallelism() − 1), each with its own server and Chromium: in the headless shell a
# file leaves a core idle part of the time (its pages waiting on timers and frames), and the four
# files left after the lanes took 58–61 s four at a time against 67–69 s two at a time, on a
# quiet machine. The longer first, as in E2E_FLEX (in alphabetical order sync.test.mjs, then 25 s,
# began last and ran on with the machine 20–56% busy). No file times the machine: how long the
# pages' tasks take on hostile input is the benchmark's (bench/long-tasks.mjs); the tests hold
# them only to a hang's bound, which the files beside them leave far off.
test-page-late: pkg www single setup-browser
	@files="$(E2E_FLEX)"; \
	if [ -n "$(E2E_SKIP_RAN)" ]; then files=$$($(CLAIM)); fi; \
	$(RUN_FOUR)

# Benchmarks, not tests: nothing here is asserted by `make test`.
bench: pkg www setup-browser
	node bench/targets.mjs --reset
	cargo bench -p kli-bench --bench core -- --warm-up-time 1 --measurement-time 3
	node bench/batch.mjs
	node bench/swarm.mjs
	node bench/spline.mjs
	node bench/smoothness.mjs
	node bench/average.mjs
	node bench/sync.mjs
	node bench/posegraphs.mjs
	node bench/poses.mjs
	node bench/size.mjs
	node bench/page.mjs
	node bench/long-tasks.mjs
	node bench/map-tasks.mjs
	node bench/first-paint.mjs
	node bench/video.mjs
	node bench/lighthouse.mjs
	node bench/targets.mjs

# Mutation testing of the core crate (cargo-mutants; not in `make test`: some 3,150 mutants, about
# six a minute here with `-j 2`, a build and the tests each). MUTANTS_ARGS passes its flags:
# `-f src/average/median.rs` for a file, `--in-diff change.diff` for a change (`git diff main >
# change.diff`), `--shard 3/8` for a share, `--iterate` to run again only what was not caught;
# after `--`, the tests to run (`-- --lib sync::`: a module's own). Results in mutants.out/;
# docs/testing.md keeps the survivors and why each cannot change a result.
MUTANTS_ARGS ?=
mutants: setup-rust
	@command -v cargo-mutants >/dev/null || cargo install cargo-mutants --version '^27'
	cargo mutants -p kli-rotations $(MUTANTS_ARGS)

# The reference values the tests check against (tests/fixtures, committed): the means from SciPy,
# the synchronised graphs from GTSAM.
fixtures:
	node scripts/fixtures.mjs

clean:
	cargo clean
	rm -rf pkg www/pkg www/examples/vendor www/vendor dist node_modules test-artifacts
