// Where the core's WASM modules are: the run's (the scenario, its run, views and pins) and the
// tools' (the same core with the challenge, grading, sweep and map bindings), fetched on the first
// job. The build (scripts/bundle.mjs) puts both beside the worker's bundle under names that carry
// their hashes, and writes this module's addresses accordingly.
export const WASM_URL = new URL('../../pkg-run/imlab_bg.wasm', import.meta.url);
export const TOOLS_WASM_URL = new URL('../../pkg/imlab_bg.wasm', import.meta.url);
