// What the page keeps on the window, for the compiler's check: the worker boot.js started with
// the page (taken by the run client), and the plot sets the browser tests and the console read.

/**
 * The worker boot.js started, what it said before the run client took it, and its failure
 * meanwhile: the error event's message (empty when the browser gives none), or a message from it
 * that could not be read. The run client says it in words.
 */
interface ImlabBoot {
  worker: Worker;
  early: import('./worker/protocol.js').FromWorker[];
  failure: { message: string; unreadable?: boolean } | null;
}

/** Undefined until boot.js or the run client sets it; null once the run client has taken it (or started its own). */
declare var imlabBoot: ImlabBoot | null | undefined;

interface Window {
  imlab: {
    plots: import('./plots/plots.js').Plots;
    walkthrough: import('./plots/plots.js').Plots;
    overlay: { column: string; data: Float64Array[] } | null;
    /** The model-error map's plot, once a map over one axis is drawn. */
    map: () => uPlot | null;
  };
}
