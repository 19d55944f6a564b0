// Pins: runs kept in the worker beside the current one, listed in the Analysis tab and kept in
// the link (`#pins=`), and the overlay that compares one column of them with the current run.
import { fixed, pageNumbers } from '../plots/numbers.js';
import { t } from '../l10n/l10n.js';
import uPlot from '../../vendor/uPlot.esm.js';
import { $, say, ui } from '../ui/page.js';
import { decodePins, fragment, setFragment } from '../ui/url.js';
import { excerpt, listed } from '../ui/quote.js';
import { el } from '../ui/dom.js';

/** @import * as P from '../worker/protocol.js' */
/** @import { State } from '../main.js' */
/** @import { RunClient } from '../client/run-client.js' */
/** @import { Plots } from '../plots/plots.js' */

// A pins fragment longer than this is refused whole (characters): four pins of the longest
// scenario the codec accepts (16 KiB each) fit.
const MAX_PINS_CHARS = 65_536;
// Pins sent to the worker from a link: one more than the core keeps, so that its refusal of the
// extra one is named.
const MAX_PINS_SENT = 5;

const COLOURS = ['#000', '#1f77b4', '#d62728', '#2ca02c', '#9467bd'];

/**
 * One overlay chart `width` px wide: `series` against the times `time`, named `names`. The current
 * run, first when it is drawn (`withCurrent`), is black; each pin keeps its colour in both charts.
 * @param {string} title
 * @param {string[]} names
 * @param {boolean} withCurrent
 * @param {Float64Array} time
 * @param {Float64Array[]} series
 * @param {number} width
 * @returns {HTMLElement}
 */
function overlayChart(title, names, withCurrent, time, series, width) {
  const div = el('div', { className: 'plot' });
  const opts = {
    title,
    width,
    height: 220,
    scales: { x: { time: false } },
    series: [
      { label: 't (s)' },
      ...names.map((name, i) => ({
        label: name,
        stroke: COLOURS[(i + (withCurrent ? 0 : 1)) % COLOURS.length],
        width: 2,
      })),
    ],
    axes: [{ label: 't (s)' }, { size: 80 }],
  };
  new uPlot(pageNumbers(opts), [time, ...series], div);
  return div;
}

/**
 * The pins of a link's fragment `shared` that are sent to the worker: none if the fragment is too
 * long, and no more than the core can take; each one left out is said.
 * @param {string} shared
 * @returns {string[] | null}
 */
function pinsFromLink(shared) {
  if (shared.length > MAX_PINS_CHARS) {
    say(t('pins-link-too-long', { length: shared.length, max: MAX_PINS_CHARS }));
    setFragment('pins', null);
    return null;
  }
  const { scenarios, malformed } = decodePins(shared);
  if (malformed.length)
    say(t('pins-link-malformed', { pins: listed(malformed.map((m) => `'${excerpt(m)}'`)), count: malformed.length }));
  // The core pins a few runs at most and names the rest; no more are sent than it can take.
  const sent = scenarios.slice(0, MAX_PINS_SENT);
  const dropped = scenarios.length - sent.length;
  if (dropped > 0) say(t('pins-link-dropped', { sent: MAX_PINS_SENT, dropped }));
  return sent;
}

/**
 * The sentence that names each scenario not pinned, and why: `Could not pin A: why; could not pin
 * B: why.`, cut after a few.
 * @param {P.PinRejected[]} rejected
 */
function rejectedSentence(rejected) {
  const clauses = rejected.map((r, i) =>
    t(i === 0 ? 'pins-rejected-first' : 'pins-rejected-next', {
      scenario: excerpt(r.scenario),
      reason: 'message' in r ? r.message : t(r.cancelled === 'unrun' ? 'pins-reason-unrun' : 'pins-reason-cancelled'),
    }),
  );
  return t('pins-rejected', { list: listed(clauses, '; ') });
}

/**
 * The pins: the list, the overlay and the link's pins; the worker's replies about them (`handlers`).
 * @param {{client: RunClient, state: State, plots: Plots}} parts
 */
export function createPins({ client, state, plots }) {
  let shared = fragment('pins'); // from the link that opened the page

  /**
   * Shows the pinned runs (with what differs from the current run) and keeps them in the link.
   * @param {string[]} scenarios
   * @param {string[]} legends
   */
  function show(scenarios, legends) {
    state.pins = scenarios;
    setFragment('pins', scenarios.length ? scenarios.map(encodeURIComponent).join('|') : null);
    $('pins').replaceChildren(
      ...scenarios.map((s, i) => {
        const unpin = el('button', { type: 'button', textContent: t('pins-unpin') });
        unpin.addEventListener('click', () => client.post({ type: 'unpin', index: i }));
        const li = el('li', { textContent: t('pins-item', { n: i + 1, legend: legends[i] ?? '' }) });
        li.append(unpin);
        return li;
      }),
    );
    requestOverlay();
  }

  function requestOverlay() {
    if (!state.pins.length) {
      $('overlay-plots').replaceChildren();
      return;
    }
    if (state.running || !plots.full) return;
    client.post({
      type: 'overlay',
      id: state.runId,
      column: $('overlay-column', HTMLSelectElement).value,
      t0: 0,
      t1: Number.MAX_VALUE,
      buckets: Math.round(plots.width()),
    });
  }

  /**
   * Overlay of the current run and the pins, and their differences (all envelopes from the core).
   * @param {string} column
   * @param {Float64Array[]} data
   */
  function drawOverlay(column, data) {
    window.imlab.overlay = { column, data };
    const n = state.pins.length;
    const label = $('overlay-column', HTMLSelectElement).selectedOptions[0].textContent;
    const pinNames = state.pins.map((_, i) => t('pins-name', { n: i + 1 }));
    $('overlay-plots').replaceChildren(
      overlayChart(
        t('pins-overlay-title', { column: label }),
        [t('pins-current'), ...pinNames],
        true,
        data[0],
        data.slice(1, 2 + n),
        plots.width(),
      ),
      overlayChart(
        t('pins-difference-title', { column: label }),
        state.pins.map((_, i) => t('pins-difference', { n: i + 1 })),
        false,
        data[0],
        data.slice(2 + n),
        plots.width(),
      ),
    );
  }

  /** After a run: pins from a shared link are re-run once; afterwards each run refreshes the comparison. */
  function afterRun() {
    if (shared) {
      const sent = pinsFromLink(shared);
      if (sent) client.post({ type: 'pin', scenarios: sent, column: $('overlay-column', HTMLSelectElement).value });
    } else if (state.pins.length) {
      client.post({ type: 'pin', scenarios: [], column: $('overlay-column', HTMLSelectElement).value });
    }
    shared = null;
  }

  // Pins the scenario the core last described (a Pin before the first description throws here).
  $('pin', HTMLButtonElement).addEventListener('click', () =>
    client.post({
      type: 'pin',
      scenarios: [/** @type {P.Info} */ (state.info).encoded],
      column: $('overlay-column', HTMLSelectElement).value,
    }),
  );
  $('overlay-column', HTMLSelectElement).addEventListener('change', requestOverlay);

  /** @type {P.Handlers} */
  const handlers = {
    'pin-progress'({ index, count, done, total }) {
      state.pinning = true;
      ui.cancel.disabled = false;
      if (!state.running) {
        ui.progress.value = done / total;
        ui.status.textContent = t('pins-status-running', {
          n: index + 1,
          count,
          percent: fixed((100 * done) / total, 0),
        });
      }
      document.body.dataset.pinning = 'running';
    },
    pins({ scenarios, legends, rejected, cancelled }) {
      if (state.pinning) {
        state.pinning = false;
        ui.cancel.disabled = !state.running && state.export === null;
        if (!state.running) ui.status.textContent = t(cancelled ? 'pins-status-cancelled' : 'pins-status-done');
      }
      document.body.dataset.pinning = cancelled ? 'cancelled' : 'done';
      if (rejected.length) say(rejectedSentence(rejected));
      show(scenarios, legends);
    },
    overlay({ id, column, data }) {
      if (id === state.runId) drawOverlay(column, data);
    },
  };

  /** Unpins every run (a lesson starts from its own state). */
  function clear() {
    shared = null;
    setFragment('pins', null);
    if (state.pinning) client.post({ type: 'pin-cancel' });
    client.post({ type: 'unpin-all' });
  }

  return { show, afterRun, clear, handlers };
}
