// Starts the simulation worker as soon as the page begins to load, before the page's modules are
// fetched and run: a browser starts a worker only when the page's thread is free, and the page's
// modules keep it busy for a few hundred milliseconds. The run client adopts this worker, with
// what it said and any failure meanwhile. The build writes this script's text into the page's head
// in place of static/index.html's reference to it, before the stylesheets (a script after them
// would wait for them), with its hash in the page's Content-Security-Policy: it runs as the head is
// parsed, with no request of its own. Should the
// page's modules start first (they cannot in practice), the run client has started the worker and
// left `imlabBoot` null, and nothing is done here. The worker's address is on this script's element
// (`data-worker`), where the build writes the name of the worker's bundle.
if (globalThis.imlabBoot === undefined) {
  const address = /** @type {string} */ (/** @type {HTMLScriptElement} */ (document.currentScript).dataset.worker);
  /** @type {ImlabBoot} */
  const boot = { worker: new Worker(address, { type: 'module' }), early: [], failure: null };
  boot.worker.onmessage = ({ data }) => boot.early.push(data);
  boot.worker.onerror = (e) => {
    e.preventDefault();
    boot.failure ??= { message: e.message };
  };
  boot.worker.onmessageerror = () => {
    boot.failure ??= { message: '', unreadable: true };
  };
  globalThis.imlabBoot = boot;
}
