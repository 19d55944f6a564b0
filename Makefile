# IM Lab build, serve and test. `make serve` and `make test` install what they need first.
.PHONY: setup wasm dist serve test bench
PORT ?= 8000
export PATH := $(HOME)/.cargo/bin:$(PATH)

setup:
	@scripts/setup.sh

wasm: setup
	wasm-pack build crate --release --target web --out-dir ../dist/pkg --no-pack -- --no-default-features
	rm -f dist/pkg/.gitignore

# A self-contained static folder that any static host can serve, with the guides in dist/docs/.
# The page's module graph (web/main.js, its imports, uPlot and KaTeX) is bundled into one minified
# module, dist/web/main.js: a load asks for one file, not one per module found level by level. The worker's
# modules stay apart, in dist/web/worker/ (the core's glue finds the WASM module beside itself).
dist: wasm
	rm -rf dist/web
	mkdir -p dist/web dist/vendor/katex/fonts
	cp static/*.html static/*.css static/*.js dist/
	cp -r web/. dist/web/
	cp node_modules/uplot/dist/uPlot.esm.js node_modules/uplot/dist/uPlot.min.css dist/vendor/
	cp node_modules/katex/dist/katex.mjs node_modules/katex/dist/katex.min.css dist/vendor/katex/
	cp node_modules/uplot/dist/uPlot.d.ts dist/vendor/uPlot.esm.d.ts
	cp node_modules/katex/types/katex.d.ts dist/vendor/katex/katex.d.mts
	node_modules/.bin/esbuild dist/web/main.js --bundle --minify --format=esm --log-level=warning --allow-overwrite --outfile=dist/web/main.js
	cp node_modules/katex/dist/fonts/*.woff2 dist/vendor/katex/fonts/
	scripts/docs_html.py dist/docs

serve: dist
	@echo "IM Lab is at http://localhost:$(PORT)/  (Ctrl-C stops it)"
	cd dist && python3 -m http.server $(PORT) --bind 127.0.0.1

test: dist
	node_modules/.bin/prettier --check --log-level=warn .
	node_modules/.bin/eslint --max-warnings=0 .
	node_modules/.bin/tsc -p tsconfig.json
	node_modules/.bin/tsc -p web/worker/tsconfig.json
	cargo fmt --all -- --check
	cargo clippy --all-targets --release -- -D warnings
	cargo clippy --lib --target wasm32-unknown-unknown --no-default-features -- -D warnings
	cargo build --release
	cargo test --release
	wasm-pack test --node crate --no-default-features
	node --test --test-concurrency=1 tests/*.test.mjs

# Criterion benchmarks (about 2 minutes after the build), the speed against the floor
# (../shared/bench/rustfloor, built by the bench), the five-state path against the build
# before the EKF's extra states (commit f3ff4f2, built by the bench), then the Node and browser
# figures.
# BENCH_ARGS goes to criterion: `make bench BENCH_ARGS=--quick` for a short pass,
# `BENCH_ARGS=long` for one group. BENCH_REPS=n sets the repetitions of the Node and browser
# figures (default 5; each prints the median). BENCH_VS_DIST=DIR adds the cold load against another
# build's dist/ folder, side by side (see tests/bench/browser.mjs).
bench: dist
	cargo bench --bench closed_loop --bench codec -- $(BENCH_ARGS)
	node tests/bench/floor.mjs
	node tests/bench/baseline.mjs
	node tests/bench/node.mjs
	node tests/bench/browser.mjs
