// The run of the scenario in the form: starting it, its progress and status line, how it ended,
// and the plots, figures and walkthrough it fills when it is done.
import { fixed, sig } from '../plots/numbers.js';
import { t } from '../l10n/l10n.js';
import { $, say, ui } from '../ui/page.js';
import { fieldValue } from '../ui/scenario.js';
import { markRun } from '../ui/url.js';
import { excerpt } from '../ui/quote.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { State } from '../main.js' */
/** @import { RunClient } from '../client/run-client.js' */
/** @import { Plots } from '../plots/plots.js' */
/** @import { Walkthrough } from '../teaching/walkthrough.js' */
/** @import { Warning, createFiguresView } from './figures-view.js' */
/** @import { createViews } from './views.js' */
/** @import { createExport } from './export.js' */

/**
 * Resolves once the browser has rendered the next frame (at once for a hidden page, and after a
 * second at most).
 */
const painted = () =>
  new Promise(
    /** @param {(value?: unknown) => void} resolve */ (resolve) => {
      if (document.hidden) {
        resolve(); // a hidden page paints nothing
        return;
      }
      requestAnimationFrame(() => setTimeout(resolve, 0));
      setTimeout(resolve, 1000);
    },
  );

/**
 * Names the run's start-up transient (null if it has none) beside the switch that fits the y-axes after it.
 * @param {State['transient']} transient
 */
function showTransient(transient) {
  ui.fitLabel.textContent = transient ? t('view-fit-from', { ms: sig(transient.t * 1e3, 3) }) : t('view-fit');
  ui.fitLabel.title = transient?.reason ?? '';
  $('fit-reason').textContent = transient ? t('view-transient-reason', { reason: transient.reason }) : '';
}

/**
 * Says how a run of `rows` samples, done in `ms`, ended: stopped early (`failure`), ran away (one
 * of its `warnings`), or done; in the status line and the page's state.
 * @param {string | null} failure
 * @param {Warning[]} warnings
 * @param {number} rows
 * @param {number} ms
 */
function reportEnd(failure, warnings, rows, ms) {
  const ranAway = warnings.find((w) => w.kind === 'runaway');
  if (failure) {
    say(t('run-stopped-early', { reason: failure, rows }));
    ui.status.textContent = t('run-status-stopped', { rows });
    document.body.dataset.state = 'failed';
  } else if (ranAway) {
    // The simulation completed, but as a control run it failed: say so before any figure.
    say(t('run-ran-away', { warning: ranAway.text }));
    ui.status.textContent = t('run-status-ran-away', { rows, ms: fixed(ms, 0) });
    document.body.dataset.state = 'failed';
  } else {
    ui.status.textContent = t('run-status-done', { rows, ms: fixed(ms, 0) });
    document.body.dataset.state = 'done';
  }
}

/**
 * Has the core built with its tools judge the own laws of run `id`, if it has any (each step with
 * one says it is being checked meanwhile), and shows the verdicts unless a newer run began.
 * @param {{client: RunClient, state: State, walkthrough: Walkthrough}} parts
 * @param {number} id
 */
function judgeLaws({ client, state, walkthrough }, id) {
  walkthrough.checkingLaws(state.ranLaws);
  if (!state.ranLaws) return;
  // A run with own laws was started: its scenario is the one it ran.
  client.job('law-verdicts', { scenario: /** @type {string} */ (state.ranScenario) }).then(
    (verdicts) => id === state.runId && walkthrough.showVerdicts(verdicts),
    (/** @type {unknown} */ e) => id === state.runId && walkthrough.verdictsFailed(e),
  );
}

/**
 * The run, started with `start()` and followed through the worker's messages (`handlers`).
 * `figuresView` shows the run's figures, `exporter` is the CSV export a new run ends, `fitEmbed()`
 * sizes an embed's plots, and `afterRun()` follows up a run that is done and drawn.
 * @param {{client: RunClient, state: State, plots: Plots, walkthrough: Walkthrough,
 *   views: ReturnType<typeof createViews>, figuresView: ReturnType<typeof createFiguresView>,
 *   exporter: ReturnType<typeof createExport>, fitEmbed: () => void, afterRun: () => void}} parts
 */
export function createRun({ client, state, plots, walkthrough, views, figuresView, exporter, fitEmbed, afterRun }) {
  let started = 0; // when the run started (performance.now())
  let fromRun = false; // whether it was started from Run, where focus returns

  /**
   * Marks a run as going on (or not): Run, Cancel and the CSV export follow.
   * @param {boolean} busy
   */
  function setBusy(busy) {
    // Run is disabled while a run goes on, which drops its focus: give it back at the end, unless
    // the user has moved on to another control.
    const refocus =
      !busy &&
      state.running &&
      fromRun &&
      /** @type {(Element | null)[]} */ ([document.body, ui.run, null]).includes(document.activeElement);
    state.running = busy;
    ui.run.disabled = busy || state.info === null;
    ui.cancel.disabled = !busy && state.export === null;
    // The worker holds one run: the one being computed, whose CSV is not whole yet.
    if (busy) ui.csv.disabled = true;
    document.body.dataset.state = busy ? 'running' : 'idle';
    if (refocus && !ui.run.disabled) ui.run.focus({ preventScroll: true });
  }

  /**
   * Marks the settings as changed and not yet run (or not), beside Run.
   * @param {boolean} unrun
   */
  function markUnrun(unrun) {
    ui.unrun.hidden = !unrun;
    if (unrun) document.body.dataset.unrun = '1';
    else delete document.body.dataset.unrun;
  }

  function start() {
    if (!state.info) return;
    markUnrun(false);
    // The first run is the link's own; a later one is the user's act, which ends the link's notice.
    if (state.runId > 0) state.notice = null;
    if (state.running) client.post({ type: 'cancel', id: state.runId });
    if (document.body.dataset.state === 'crashed') say(''); // the crash was told; this is the retry
    // The new run replaces the one being exported in the worker.
    if (state.export) {
      exporter.cancel(t('export-csv-cancelled'));
      say(t('export-csv-cancelled-by-run'), 'info');
    }
    const id = ++state.runId;
    state.ranScenario = state.info.encoded;
    state.ranLaws = state.info.fields.some((f) => !!f.formula && !!f.value);
    markRun(state.info.encoded);
    fromRun = document.activeElement === ui.run; // started from Run: focus returns there
    document.body.dataset.scenario = state.info.encoded;
    document.body.dataset.started = String(id); // runs started: tests wait on it, not on a time
    started = performance.now();
    ui.progress.value = 0;
    ui.status.textContent = t('run-status-starting', { samples: state.info.steps });
    walkthrough.closeInspect();
    setBusy(true);
    // The run keeps the whole-run view of the main plots, and of the walkthrough's once it has been
    // opened (until then they ask for theirs when it is, and a run does not pay for them).
    const groups = { ...plots.groups(), ...(walkthrough.opened ? walkthrough.plots.groups() : {}) };
    // With runs pinned, the run keeps the overlay's column as it goes.
    const overlay = state.pins.length ? $('overlay-column', HTMLSelectElement).value : null;
    client.post({ type: 'run', id, scenario: state.info.encoded, groups, buckets: views.buckets(), overlay });
  }

  /**
   * The worker failed (RunClient): the run and its export are gone with it; says so.
   * @param {string} reason
   * @param {boolean} restarting
   */
  function workerFailed(reason, restarting) {
    if (state.export) exporter.end('failed', t('export-csv-stopped'));
    const wasRunning = state.running;
    state.pinning = false;
    setBusy(false);
    ui.csv.disabled = true;
    document.body.dataset.state = 'crashed';
    if (wasRunning) ui.status.textContent = t('run-status-worker-failed');
    if (!restarting) {
      say(t('run-worker-not-started', { reason }));
      return;
    }
    const pins = state.pins.map((p) => excerpt(p)).join('; ');
    say(t(state.pins.length ? 'run-worker-failed-pins' : 'run-worker-failed', { reason, pins }));
  }

  /** @type {P.Handlers} */
  const handlers = {
    invalid({ id, message, comparison }) {
      if (id === state.runId) {
        setBusy(false);
        say(comparison ? t('compare-failed', { reason: message }) : message);
      }
    },
    progress({ id, done, total }) {
      if (id !== state.runId) return;
      ui.progress.value = done / total;
      ui.status.textContent = t('run-status-progress', { done, total });
    },
    async done({ id, rows, failure, view, computeMs, stability, figures, unreached, transient, warnings, ...derived }) {
      if (id !== state.runId) return;
      setBusy(false);
      ui.progress.value = 1;
      const arrived = performance.now();
      judgeLaws({ client, state, walkthrough }, id);
      state.transient = transient;
      state.figures = figures;
      state.unreached = unreached;
      // The plots first: they read the page's layout before the rest of the run changes it.
      if (view) plots.show(view, { ifoc: fieldValue(state.info, 'controller') === 'ifoc' });
      showTransient(transient);
      figuresView.show(figures, warnings, unreached, derived);
      if (view) {
        state.shownRun = id;
        walkthrough.show(stability, state.nisBand);
        // The walkthrough's plots are in the view once it has been opened.
        if (walkthrough.plots.defs.every((p) => p.id in view.plots)) walkthrough.receive(view);
        fitEmbed();
        // "Plotted" is when the browser has painted them: the canvases are rasterised then.
        await painted();
        // A newer run, or a worker crash while the plots were drawn, owns the page now.
        if (id !== state.runId || document.body.dataset.state === 'crashed') return;
        views.walkthroughView();
      }
      const ms = performance.now() - started;
      Object.assign(document.body.dataset, {
        plotMs: (performance.now() - arrived).toFixed(1),
        runMs: ms.toFixed(1),
        rows,
        computeMs: computeMs.toFixed(2),
        run: id,
      });
      ui.csv.disabled = ui.png.disabled = rows === 0;
      reportEnd(failure, warnings, rows, ms);
      afterRun();
    },
    cancelled({ id }) {
      if (id !== state.runId) return;
      setBusy(false);
      ui.status.textContent = t('run-status-cancelled', { percent: fixed(ui.progress.value * 100, 0) });
      document.body.dataset.state = 'cancelled';
    },
  };

  return { start, setBusy, markUnrun, workerFailed, handlers };
}
