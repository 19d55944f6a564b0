// Where the worker's module is, for the run client and the pools. Kept at the root of web/ so that
// the address is the same from the sources and from the bundle, dist/web/main.js, whose
// import.meta.url is this folder's.
export const WORKER_URL = new URL('./worker/worker.js', import.meta.url);
