// The tabs (Trajectories, Design walkthrough, Lessons, Analysis): which panel is shown, chosen by
// a click or by the arrow keys, Home and End.
import { $ } from './page.js';

/**
 * `walkthroughView()` asks for the last run's walkthrough view if it lacks one.
 * @param {{plots: import('../plots/plots.js').Plots, walkthrough: import('../teaching/walkthrough.js').Walkthrough,
 *   walkthroughView: () => void}} parts
 */
export function createTabs({ plots, walkthrough, walkthroughView }) {
  const TABS = [.../** @type {NodeListOf<HTMLElement>} */ (document.querySelectorAll('[role=tab]'))];
  for (const tab of TABS) {
    const panel = $(`panel-${tab.dataset.tab}`, HTMLDivElement);
    if (!panel.hidden) panel.dataset.shown = '';
  }

  /**
   * Shows tab `name`; with `fetch`, the walkthrough asks for the last run's view if it lacks it.
   * @param {string} name
   * @param {{fetch?: boolean}} [options]
   */
  function showTab(name, { fetch = true } = {}) {
    for (const tab of TABS) {
      const selected = tab.dataset.tab === name;
      tab.setAttribute('aria-selected', String(selected));
      tab.tabIndex = selected ? 0 : -1; // one tab stop for the tab list (WAI-ARIA tabs pattern)
      const panel = $(`panel-${tab.dataset.tab}`, HTMLDivElement);
      panel.hidden = !selected;
      // The style keeps a hidden panel laid out once it has been shown (skipped, see style.css):
      // out of the accessibility tree as the `hidden` attribute alone would put it.
      if (selected) {
        panel.dataset.shown = '';
        panel.removeAttribute('aria-hidden');
      } else panel.setAttribute('aria-hidden', 'true');
    }
    // A panel hidden after it was shown keeps its layout (style.css), so its plots keep their
    // size; the shown ones are sized in case the window changed meanwhile, or were drawn while
    // their panel was not displayed yet (a chart of the right size is left alone).
    if (name === 'plots') plots.resize();
    if (name === 'walkthrough') {
      walkthrough.shown();
      if (fetch) walkthroughView();
      walkthrough.plots.resize();
    }
    walkthrough.closeInspect();
  }

  for (const tab of TABS) tab.addEventListener('click', () => showTab(/** @type {string} */ (tab.dataset.tab)));
  // Arrow keys, Home and End move between tabs and select them.
  /** @type {HTMLElement} */ (document.querySelector('[role=tablist]')).addEventListener('keydown', (e) => {
    const i = TABS.indexOf(/** @type {HTMLElement} */ (document.activeElement));
    const to = /** @type {Partial<Record<string, number>>} */ ({
      ArrowRight: i + 1,
      ArrowLeft: i - 1,
      Home: 0,
      End: TABS.length - 1,
    })[e.key];
    if (i < 0 || to === undefined) return;
    e.preventDefault();
    const tab = TABS[(to + TABS.length) % TABS.length];
    showTab(/** @type {string} */ (tab.dataset.tab));
    tab.focus();
  });

  return { showTab };
}
