// Where the walkthrough's content sits on screen: whether an element is rendered, sideways scroll
// boxes reachable from the keyboard, an inspected plot kept in view above the inspect sheet, and a
// lesson's plot brought whole into view.

/**
 * @param {Element} e
 * @param {Record<string, string>} attributes
 */
function setAttributes(e, attributes) {
  for (const [name, value] of Object.entries(attributes)) e.setAttribute(name, value);
}

/**
 * Whether `element` is rendered: not under a hidden tab's panel, which is skipped
 * (`content-visibility`, style.css) once shown where the browser has it, and not displayed
 * otherwise.
 * @param {HTMLElement} element
 */
export function rendered(element) {
  return element.checkVisibility?.() ?? element.offsetParent !== null;
}

// A box that scrolls sideways (a long equation, a wide table) must be reachable from the keyboard
// and named; one that fits stays out of the tab order, so the walkthrough does not gain a tab stop
// per equation on a wide screen. Checked whenever a box changes size and when the tab is shown:
// every box is measured before any is marked, so that the page is laid out once, not once a box.
/** @param {HTMLElement[]} boxes */
export function markScrollable(boxes) {
  const scrolls = boxes.map((box) => box.scrollWidth > box.clientWidth + 1);
  boxes.forEach((box, i) => {
    if (scrolls[i] === (box.getAttribute('role') === 'region')) return;
    if (scrolls[i]) {
      setAttributes(box, { tabindex: '0', role: 'region', 'aria-label': /** @type {string} */ (box.dataset.label) });
    } else {
      for (const name of ['tabindex', 'role', 'aria-label']) box.removeAttribute(name);
    }
  });
}
// The sideways scroll boxes (`scrollBox` registers them), each marked again when it changes size.
const scrollBoxes = new ResizeObserver((entries) =>
  markScrollable(entries.map((e) => /** @type {HTMLElement} */ (e.target))),
);

/**
 * Registers `box` as a sideways scroll box named `label`.
 * @template {HTMLElement} E
 * @param {E} box
 * @param {string} label
 * @returns {E}
 */
export function scrollBox(box, label) {
  box.dataset.label = label;
  box.classList.add('scroll-box');
  scrollBoxes.observe(box);
  return box;
}

/**
 * Keeps `plot`, the plot the sample was picked on, in view above the sheet `box`: caps the sheet
 * at the room the plot leaves (but not under about ten lines), gives the page that much room at
 * its end, and scrolls the plot into the space above the sheet. If the whole figure cannot fit,
 * its title and canvas do.
 * @param {HTMLElement} box
 * @param {HTMLElement | null} plot
 */
export function keepAboveSheet(box, plot) {
  box.style.maxHeight = '';
  const visible = plot?.isConnected && rendered(plot);
  const rem = parseFloat(getComputedStyle(document.documentElement).fontSize);
  const gap = 0.5 * rem;
  if (visible) {
    const room = innerHeight - plot.getBoundingClientRect().height - 2 * gap;
    const full = box.offsetHeight;
    if (room < full) box.style.maxHeight = `${Math.max(room, Math.min(full, 10 * rem))}px`;
  }
  const height = box.offsetHeight;
  document.documentElement.style.setProperty('--inspect-height', `${height}px`);
  if (!visible) return;
  const whole = plot.getBoundingClientRect();
  const limit = innerHeight - height - gap;
  const canvas = plot.querySelector('.u-wrap') ?? plot;
  const bottom = whole.height <= limit - gap ? whole.bottom : canvas.getBoundingClientRect().bottom;
  let dy = bottom > limit ? bottom - limit : 0;
  if (whole.top - dy < gap) dy = whole.top - gap;
  if (Math.abs(dy) >= 1) window.scrollBy(0, dy);
}

// The room kept between a plot brought into view and the window's edges (px).
const EDGE = 8;

/**
 * Scrolls the page as little as brings `element` whole into view; its top, where it is taller
 * than the window.
 * @param {HTMLElement} element
 */
export function keepWhole(element) {
  const box = element.getBoundingClientRect();
  let dy = box.bottom > innerHeight - EDGE ? box.bottom - (innerHeight - EDGE) : 0;
  if (box.top - dy < EDGE) dy = box.top - EDGE;
  if (Math.abs(dy) >= 1) window.scrollBy(0, dy);
}
