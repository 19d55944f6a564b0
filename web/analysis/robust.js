// The Analysis tab's model-error map: the current scenario over one or two motor or model
// parameters times the noise seeds, run cell by cell in the pool's workers. The core checks and
// bounds the map, runs each cell and summarises it; this module runs it and keeps what it returns
// (map-view.js draws it). A link's map (`#robust=`) runs once; a cancelled map keeps the cells it
// finished.
import { $ } from '../ui/page.js';
import { Pool } from '../client/pool.js';
import { download } from '../ui/dom.js';
import { setFragment } from '../ui/url.js';
import { fillMapForm, mapFormParts } from './map-form.js';
import { chosenFigure, drawMap } from './map-view.js';
import { runFromLink } from './from-link.js';
import { num, restReady, t } from '../l10n/l10n.js';
import { integer } from './digits.js';

/** @typedef {import('../worker/protocol.js').Info} Info */

/**
 * A map as the core checks it (its axes, its cells' plans, the seeds, its work and its text), one
 * run of one cell, a cell's row as the core summarises its runs, and a figure a map keeps: the
 * core's own types.
 * @typedef {import('../worker/protocol.js').Jobs['map-plan']['result']['map']} RobustMap
 * @typedef {RobustMap['axes'][number]} MapAxis
 * @typedef {RobustMap['cells'][number]} CellPlan
 * @typedef {import('../worker/protocol.js').Jobs['map-run']['result']} MapRun
 * @typedef {import('../worker/protocol.js').Jobs['map-cells']['result'][number]} MapCell
 * @typedef {import('../worker/protocol.js').Jobs['map-plan']['result']['figures'][number]} MapFigure
 */
/**
 * A map as drawn: the cells kept (`map`), the map asked for (`full`), the rows of the cells that
 * finished, the figures a cell has, and which cells of the full map finished.
 * @typedef {{map: RobustMap, full: RobustMap, cells: MapCell[], figures: MapFigure[],
 *   whole: boolean[]}} Drawn
 */

/**
 * Enables Run and Cancel for a map that runs (`running`) or not.
 * @param {boolean} running
 */
function setRunning(running) {
  $('map-run', HTMLButtonElement).disabled = running;
  $('map-cancel', HTMLButtonElement).disabled = !running;
}

/**
 * Runs every seed of every cell of `map` in `pool`, showing the progress in `status` and
 * `progress`. Resolves with the runs (a job's result at its index), which cells finished all their
 * seeds, and whether the map was cancelled; rejects if a run failed.
 * @param {Pool} pool
 * @param {RobustMap} map
 * @param {HTMLElement} status
 * @param {HTMLProgressElement} progress
 * @returns {Promise<{runs: MapRun[], whole: boolean[], cancelled: boolean}>}
 */
async function runCells(pool, map, status, progress) {
  const per = map.seeds.length;
  const total = map.cells.length * per;
  /** @type {MapRun[]} */
  const runs = new Array(total);
  const finished = new Array(map.cells.length).fill(0);
  let cellsDone = 0;
  let cancelled = false;
  try {
    const jobs = map.cells.flatMap((c) =>
      map.seeds.map((seed) => ({ kind: /** @type {const} */ ('map-run'), scenario: c.scenario, seed })),
    );
    await pool.run(jobs, (done, index, result) => {
      runs[index] = result;
      if (++finished[Math.floor(index / per)] === per) document.body.dataset.mapCells = String(++cellsDone);
      progress.value = done / total;
      status.textContent = t('map-status-running', { done: integer(done), total: integer(total) });
    });
  } catch (e) {
    if (/** @type {Error} */ (e).message !== 'cancelled') throw e;
    cancelled = true;
  }
  return { runs, whole: finished.map((n) => n === per), cancelled };
}

/**
 * `analysis` holds the worker pool; `open(scenario)` runs a scenario on the Plots tab; `state.info`
 * is the core's description of the scenario in the form, which a map runs (null until the first),
 * once `current()` has made it the run on screen; `stale` marks the map while it is of an earlier
 * scenario. `scale()` is the plots' text scale (larger in presentation mode); `drawn()` follows
 * each drawing of the map.
 * @param {{state: {info: Info | null}, analysis: import('./analysis.js').Analysis,
 *   open: (scenario: string) => void, showTab: (name: string) => void, current: () => Promise<boolean>,
 *   stale: ReturnType<typeof import('../ui/stale.js').createStale>, scale: () => number,
 *   drawn: () => void}} parts
 */
export function createRobust({ state, analysis, open, showTab, current, stale, scale, drawn }) {
  /** @type {Drawn | null} */
  let last = null; // the map drawn
  /** @type {uPlot | null} */
  let chart = null; // its plot
  // The map's own workers for its runs: a sweep or a seed run on the Analysis tab's other pool
  // neither waits for it nor cancels it. The plan, the summary and the CSV are quick jobs of the
  // run worker, which outlives a Cancel (it terminates the pool's workers): a cancelled map's
  // summary does not wait for fresh workers to load the core.
  const pool = new Pool(analysis.pool.size);
  const form = $('map-form', HTMLFormElement);
  const status = $('map-status');
  const progress = $('map-progress', HTMLProgressElement);
  // The map's CSV stays on while the map is of an earlier scenario: it names that scenario.
  const shown = stale.add({
    name: 'map',
    before: $('map-plot'),
    shows: [$('map-plot')],
    back: true,
  });

  /**
   * Fills the form from a map's text, split by the core (in the run worker, so that a map under
   * way goes on); rejects with the core's message.
   * @param {string} text
   */
  const fill = async (text) => fillMapForm(form, await analysis.client.job('map-parts', { text }));

  /**
   * The core's plan of the form's map over `scenario`, or null (said) if it refuses it.
   * @param {string} scenario
   * @returns {Promise<{map: RobustMap, figures: MapFigure[]} | null>}
   */
  async function plan(scenario) {
    try {
      return await analysis.client.job('map-plan', { scenario, ...mapFormParts(form) });
    } catch (e) {
      status.textContent = t('map-refused', { reason: /** @type {Error} */ (e).message });
      document.body.dataset.map = 'refused';
      return null;
    }
  }

  async function runMap() {
    // Its words are of the rest of the page's messages.
    const unready = await restReady();
    if (unready) return void (status.textContent = unready);
    if (!(await current())) {
      status.textContent = t('map-not-run');
      document.body.dataset.map = 'refused';
      return;
    }
    const scenario = /** @type {Info} */ (state.info).encoded;
    const planned = await plan(scenario);
    if (!planned) return;
    const { map, figures } = planned;
    setFragment('robust', encodeURIComponent(map.text));
    const per = map.seeds.length;
    setRunning(true);
    $('map-csv', HTMLButtonElement).disabled = true;
    progress.value = 0;
    Object.assign(document.body.dataset, { map: 'running', mapCells: '0' });
    status.textContent = t('map-status-starting', { cells: integer(map.cells.length), seeds: integer(per) });
    const started = performance.now();
    let ran;
    try {
      ran = await runCells(pool, map, status, progress);
    } catch (e) {
      status.textContent = t('map-failed', { reason: /** @type {Error} */ (e).message });
      document.body.dataset.map = 'failed';
      setRunning(false);
      return;
    }
    const { runs, whole, cancelled } = ran;
    // The cells whose every seed finished (all of them unless cancelled); the summary that
    // follows cannot be cancelled, so that what finished is kept.
    $('map-cancel', HTMLButtonElement).disabled = true;
    const kept = { ...map, cells: map.cells.filter((_, i) => whole[i]) };
    try {
      const cells = await analysis.client.job('map-cells', {
        map: kept,
        runs: runs.filter((_, i) => whole[Math.floor(i / per)]),
      });
      last = { map: kept, full: map, cells, figures, whole };
      draw();
      shown.ran(scenario);
      const ms = performance.now() - started;
      status.textContent = cancelled
        ? t('map-status-cancelled', { finished: integer(cells.length), cells: integer(map.cells.length) })
        : t('map-status-done', {
            cells: integer(map.cells.length),
            seeds: integer(per),
            first: String(map.seeds[0]),
            last: String(map.seeds.at(-1)),
            seconds: num(ms / 1000, 1),
          });
      document.body.dataset.map = cancelled ? 'cancelled' : 'done';
      $('map-csv', HTMLButtonElement).disabled = cells.length === 0;
    } catch (e) {
      status.textContent = t('map-failed', { reason: /** @type {Error} */ (e).message });
      document.body.dataset.map = 'failed';
    } finally {
      setRunning(false);
    }
  }

  /** Draws the last map, once there is one. */
  function draw() {
    const map = /** @type {Drawn} */ (last);
    $('map-figure-label').hidden = false;
    // The chart drawn before keeps listeners on the window until it is destroyed.
    chart?.destroy();
    chart = drawMap($('map-plot'), map, chosenFigure($('map-figure', HTMLSelectElement), map.figures), open, scale());
    drawn();
  }

  /** After a run: a shared link with a map in its fragment runs that map, once. */
  const afterRun = runFromLink({
    name: 'robust',
    refused: 'map-link-refused',
    fill: (text) => fill(decodeURIComponent(text)),
    run: runMap,
    showTab,
  });

  $('map-run', HTMLButtonElement).addEventListener('click', runMap);
  $('map-cancel', HTMLButtonElement).addEventListener('click', () => pool.cancel());
  $('map-figure', HTMLSelectElement).addEventListener('change', () => last && draw());
  $('map-csv', HTMLButtonElement).addEventListener('click', async () => {
    // CSV is enabled only once a map is drawn.
    const drawn = /** @type {Drawn} */ (last);
    const csv = await analysis.client.job('map-csv', { map: drawn.full, cells: drawn.cells });
    download(new Blob([csv], { type: 'text/csv' }), 'imlab-robust.csv');
  });

  // The map drawn again, at the plots' scale (after presentation mode is switched); its plot.
  return { afterRun, fill, redraw: () => last && draw(), chart: () => chart };
}
