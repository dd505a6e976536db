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
# Features the Rust wasm32 target emits; wasm-opt must accept them.
WASM_FEATURES := --enable-bulk-memory --enable-nontrapping-float-to-int --enable-sign-ext \
                 --enable-mutable-globals --enable-reference-types --enable-multivalue --enable-simd

.PHONY: help setup setup-rust setup-node setup-browser pkg demo serve test test-native \
        test-wasm-node test-wasm-browser test-package test-page bench clean

help:
	@echo "make demo   build and serve the demo page at http://127.0.0.1:$(PORT)/"
	@echo "make test   run every test (native, wasm under Node, package, headless Chromium)"
	@echo "make pkg    build the npm package into pkg/"
	@echo "make bench  run the benchmarks"

setup: setup-rust setup-node setup-browser

setup-rust:
	@rustup target list --installed | grep -qx $(TARGET) || rustup target add $(TARGET)
	@if [ "$$(wasm-bindgen --version 2>/dev/null)" != "wasm-bindgen $(WASM_BINDGEN_VERSION)" ]; then \
	  echo "installing wasm-bindgen-cli $(WASM_BINDGEN_VERSION) (about 2.5 minutes, once)"; \
	  cargo install wasm-bindgen-cli --version $(WASM_BINDGEN_VERSION); \
	fi

# node_modules is reinstalled whenever package-lock.json is newer than it.
setup-node: node_modules/.installed
node_modules/.installed: package.json package-lock.json
	npm ci --no-audit --no-fund
	@touch $@

setup-browser:
	@if ! command -v chromium >/dev/null || ! command -v chromedriver >/dev/null; then \
	  echo "installing Debian's chromium and chromium-driver (about a minute, once)"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver >/dev/null; \
	fi

pkg: setup-rust setup-node
	cargo build --release --lib --target $(TARGET)
	rm -rf pkg
	wasm-bindgen --target web --out-dir pkg --out-name kli target/$(TARGET)/release/kli.wasm
	wasm-opt -O3 $(WASM_FEATURES) pkg/kli_bg.wasm -o pkg/kli_bg.wasm
	cp README.md pkg/
	node scripts/package-json.mjs
	@echo "pkg/kli_bg.wasm: $$(stat -c %s pkg/kli_bg.wasm) bytes, $$(gzip -9c pkg/kli_bg.wasm | wc -c) gzipped"

www/pkg: pkg
	rm -rf www/pkg && cp -r pkg www/pkg

demo: www/pkg
	@echo "Serving the demo at http://127.0.0.1:$(PORT)/  (Ctrl-C to stop)"
	python3 -m http.server $(PORT) --bind 127.0.0.1 --directory www

test: test-native test-wasm-node test-package test-wasm-browser test-page

test-native:
	cargo test

test-wasm-node: setup-rust
	WASM_BINDGEN_TEST_ONLY_NODE=1 cargo test --target $(TARGET) --tests

test-wasm-browser: setup-rust setup-browser
	WASM_BINDGEN_TEST_ONLY_WEB=1 cargo test --target $(TARGET) --tests

test-package: www/pkg
	node --test tests/js/

test-page: www/pkg setup-browser
	node --test tests/e2e/

# Benchmarks, not tests: nothing here is asserted by `make test`.
bench: www/pkg setup-browser
	cargo bench -p kli-bench --bench core -- --warm-up-time 1 --measurement-time 3
	node bench/batch.mjs
	node bench/page.mjs

clean:
	cargo clean
	rm -rf pkg www/pkg node_modules test-artifacts
