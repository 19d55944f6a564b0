// The page's DOM helpers: making an element, and putting work off until the page is idle.

/** A new `tag` element with `props` assigned and `children` appended. */
export function el(tag, props = {}, children = []) {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
}

/**
 * Runs `task` when the page is next idle (within a second), or soon where the browser does not
 * tell idle time: for work nothing on screen waits for.
 * @param {() => void} task
 */
export function whenIdle(task) {
  if (globalThis.requestIdleCallback) requestIdleCallback(task, { timeout: 1000 });
  else setTimeout(task, 50);
}
