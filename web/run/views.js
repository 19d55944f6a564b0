// What the plots ask the worker about the last run: a zoom window, the whole run again, the
// state at one time (inspect), and the walkthrough's own view and predictor comparison.
import { $ } from '../ui/page.js';
import { fieldValue } from '../ui/scenario.js';
import { t } from '../l10n/l10n.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { State } from '../main.js' */
/** @import { RunClient } from '../client/run-client.js' */
/** @import { Plots } from '../plots/plots.js' */
/** @import { Walkthrough } from '../teaching/walkthrough.js' */

/**
 * The plots' requests of the worker about the last run, and its replies (`handlers`); the
 * predictor comparison is marked by `stale` while it is of an earlier scenario.
 * @param {{client: RunClient, state: State, plots: Plots, walkthrough: Walkthrough,
 *   stale: ReturnType<typeof import('../ui/stale.js').createStale>}} parts
 */
export function createViews({ client, state, plots, walkthrough, stale }) {
  const plotSets = [plots, walkthrough.plots];
  let walkthroughAsked = 0; // the run whose whole-run walkthrough view was asked for

  // One bucket a pixel column of the widest plot.
  const buckets = () => Math.max(200, Math.round(plots.width()));

  /** Whether the worker holds the run the plots show (not a later one that was cancelled, refused or recorded nothing). */
  const showingLastRun = () => !state.running && plots.full !== null && state.shownRun === state.runId;

  /**
   * @param {number} t0
   * @param {number} t1
   */
  function requestWindow(t0, t1) {
    if (!showingLastRun()) return;
    // A window that holds the whole run is the whole run: the charts hold it already, and for a run
    // of a million rows each request would cost the worker seconds.
    const full = /** @type {[number, number]} */ (plots.full); // the run shown has one
    if (t0 <= full[0] && t1 >= full[1]) return;
    for (const set of plotSets) set.follow(t0, t1);
    requestViews(t0, t1);
  }

  /** Returns every plot to the whole run. */
  function fullRun() {
    if (!showingLastRun()) return;
    for (const set of plotSets) set.unzoom();
    requestViews(0, Number.MAX_VALUE);
  }

  /**
   * Asks for a window of the main plots, and of the walkthrough's once they show this run.
   * @param {number} t0
   * @param {number} t1
   */
  function requestViews(t0, t1) {
    requestView('plots', t0, t1);
    if (walkthrough.drawn()) requestView('walkthrough', t0, t1);
  }

  /**
   * @param {'plots' | 'walkthrough'} set
   * @param {number} t0
   * @param {number} t1
   */
  function requestView(set, t0, t1) {
    const groups = (set === 'walkthrough' ? walkthrough.plots : plots).groups();
    client.post({ type: 'view', id: state.runId, set, groups, t0, t1, buckets: buckets() });
  }

  /** Asks for the walkthrough's view of the whole run when it is on screen and does not have it yet. */
  function walkthroughView() {
    if (!showingLastRun() || !walkthrough.stale || !walkthrough.visible()) return;
    if (walkthroughAsked === state.runId) return; // asked already
    walkthroughAsked = state.runId;
    requestView('walkthrough', 0, Number.MAX_VALUE);
  }

  /** @param {number} t */
  function requestInspect(t) {
    if (!state.running && plots.full) client.post({ type: 'inspect', id: state.runId, t });
  }

  /** @type {ReturnType<typeof stale.add> | null} the comparison's mark, once it has a box */
  let compared = null;
  /** The comparison's box (its section is built with it) and its mark. */
  function comparison() {
    const box = /** @type {HTMLElement} */ ($('walkthrough').querySelector('.compare-result'));
    // Its mark says the message stale-compare.
    compared ??= stale.add({ name: 'compare', before: box, shows: [box] });
    return { box, mark: compared };
  }

  function compare() {
    const { box, mark } = comparison();
    box.textContent = t('compare-running');
    mark.forget();
    client.post({ type: 'compare', id: state.runId });
  }

  /** @type {P.Handlers} */
  const handlers = {
    view({ id, set, view }) {
      if (id !== state.runId) return;
      if (set === 'walkthrough') {
        walkthrough.receive(view);
      } else {
        plots.refine(view);
        document.body.dataset.view = `${view.t0},${view.t1}`;
      }
    },
    inspected({ id, t, snapshot }) {
      if (id === state.runId) walkthrough.inspect(snapshot, t, Number(fieldValue(state.info, 'ts')));
    },
    compared({ id, results }) {
      if (id !== state.runId) return;
      walkthrough.showComparison(results);
      comparison().mark.ran(/** @type {string} */ (state.ranScenario));
    },
  };

  return { buckets, requestWindow, fullRun, walkthroughView, requestInspect, compare, handlers };
}
