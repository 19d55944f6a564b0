// What the page keeps on the window, for the compiler's check: the worker boot.js started with
// the page (taken by the run client), and the plot sets the browser tests and the console read.
interface Window {
  imlabBoot: { worker: Worker; early: any[]; failure: string | null } | null;
  imlab: { plots: any; walkthrough: any; overlay: { column: string; data: Float64Array[] } | null };
}
