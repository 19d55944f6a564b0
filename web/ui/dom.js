// The page's DOM helpers: making an element, saving a download, and putting work off until the page is idle.

/**
 * A new `tag` element with `props` assigned and `children` appended.
 * @template {keyof HTMLElementTagNameMap} T
 * @param {T} tag
 * @param {Partial<HTMLElementTagNameMap[T]>} [props]
 * @param {(Node | string)[]} [children]
 * @returns {HTMLElementTagNameMap[T]}
 */
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
  if (/** @type {typeof requestIdleCallback | undefined} */ (globalThis.requestIdleCallback))
    requestIdleCallback(task, { timeout: 1000 });
  else setTimeout(task, 50);
}

// The browser reads a blob: URL while it saves the download, which for a CSV of a gigabyte
// takes seconds; revoking the URL earlier would fail the download.
const REVOKE_AFTER_MS = 120_000;

/**
 * Saves `blob` as a download named `name`.
 * @param {Blob} blob
 * @param {string} name
 */
export function download(blob, name) {
  const a = el('a', { href: URL.createObjectURL(blob), download: name });
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), REVOKE_AFTER_MS);
}
