// Where the worker's module is, for the run client and the pools. The build (scripts/bundle.mjs)
// bundles the worker beside the page's bundle under a name that carries its hash, and writes this
// module's address accordingly.
export const WORKER_URL = new URL('./worker/worker.js', import.meta.url);
