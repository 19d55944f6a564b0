# IM Lab build, serve and test. `make serve` and `make test` install what they need first.
.PHONY: setup wasm dist serve test bench
PORT ?= 8000
export PATH := $(HOME)/.cargo/bin:$(PATH)

setup:
	@scripts/setup.sh

# Two builds of the core: pkg-run/ runs a scenario (the page's first fetch), pkg/ adds the tools'
# bindings (challenges, grading, sweeps, maps; fetched on the first tool used, and the Node tests').
wasm: setup
	wasm-pack build crate --release --target web --out-dir ../dist/pkg --no-pack -- --no-default-features --features tools
	wasm-pack build crate --release --target web --out-dir ../dist/pkg-run --no-pack -- --no-default-features
	rm -f dist/pkg/.gitignore dist/pkg-run/.gitignore

# A self-contained static folder that any static host can serve, with the guides in dist/docs/.
# scripts/bundle.mjs builds the page: each file it loads before its first plot minified and named by
# its content's hash (the page's modules in one, the worker's and the core's glue in another, KaTeX
# in a chunk fetched when an equation is first shown). scripts/compress.mjs writes a brotli and a
# gzip copy beside each file. The core's module and glue stay in dist/pkg/ too, for the Node tests.
dist: wasm
	mkdir -p dist/vendor/katex/fonts
	cp static/structure.svg dist/
	cp node_modules/uplot/dist/uPlot.esm.js node_modules/uplot/dist/uPlot.min.css dist/vendor/
	cp node_modules/katex/dist/katex.mjs node_modules/katex/dist/katex.min.css dist/vendor/katex/
	cp node_modules/uplot/dist/uPlot.d.ts dist/vendor/uPlot.esm.d.ts
	cp node_modules/katex/types/katex.d.ts dist/vendor/katex/katex.d.mts
	cp node_modules/katex/dist/fonts/*.woff2 dist/vendor/katex/fonts/
	node scripts/bundle.mjs dist
	scripts/docs_html.py dist/docs
	node scripts/compress.mjs dist

# Serves dist/ as a static host would: precompressed files, content types, cache headers.
serve: dist
	node scripts/serve.mjs --port $(PORT)

test: dist
	node_modules/.bin/prettier --check --log-level=warn .
	node_modules/.bin/eslint --max-warnings=0 .
	node_modules/.bin/tsc -p tsconfig.json
	node_modules/.bin/tsc -p web/worker/tsconfig.json
	node_modules/.bin/tsc -p tsconfig.bindings.json
	cargo fmt --all -- --check
	cargo clippy --all-targets --release -- -D warnings
	cargo clippy --lib --target wasm32-unknown-unknown --no-default-features -- -D warnings
	cargo clippy --lib --target wasm32-unknown-unknown --no-default-features --features tools -- -D warnings
	cargo build --release
	cargo test --release
	wasm-pack test --node crate --no-default-features --features tools
	node --test --test-concurrency=2 tests/*.test.mjs

# Criterion benchmarks (about 2 minutes after the build), the speed against the floor
# (../shared/bench/rustfloor, built by the bench), the five-state path against the build
# before the EKF's extra states (commit f3ff4f2, built by the bench), then the Node and browser
# figures.
# BENCH_ARGS goes to criterion: `make bench BENCH_ARGS=--quick` for a short pass,
# `BENCH_ARGS=long` for one group. BENCH_REPS=n sets the repetitions of the Node and browser
# figures (default 5; each prints the median). BENCH_VS_DIST=DIR adds the cold load against another
# build's dist/ folder, side by side (see tests/bench/browser.mjs), and the first load under
# throttled networks and CPUs, compressed and not, against that build too (tests/bench/throttled.mjs),
# and the page thread's work before the first plot on school Wi-Fi (tests/bench/thread.mjs).
bench: dist
	cargo bench --bench closed_loop --bench codec -- $(BENCH_ARGS)
	node tests/bench/floor.mjs
	node tests/bench/baseline.mjs
	node tests/bench/node.mjs
	node tests/bench/browser.mjs
	node tests/bench/throttled.mjs
	node tests/bench/thread.mjs
