// What a run's results say in the walkthrough: the stability report (V against its bound) and the
// table comparing the Euler and RK4 predictors. The figures come from the core; this formats them.
import { el } from '../ui/dom.js';
import { percent } from '../plots/numbers.js';
import { STABILITY_CAUSES } from './walkthrough-text.js';
import { TABLE } from './table.js';
import { render } from './measured.js';

/**
 * The metrics of a finished run that recorded something.
 * @typedef {NonNullable<import('../worker/protocol.js').Compared['results'][number]['metrics']>} Metrics
 */

/**
 * The stability report `st` of a run, in words.
 * @param {import('../worker/protocol.js').Done['stability']} st
 */
export function stabilityText(st) {
  if (!st) return 'Nothing was recorded.';
  const b = st.bound;
  const head = `λ = 2·min(k) = ${b.lambda} 1/s, ε = ${b.eps} (${b.eps ? 'robust terms on' : 'robust terms off, so the bound is V(0)·e^(−λt)'}). `;
  if (st.outside === 0) return `${head}V stays under the bound at all ${st.samples} samples.`;
  const why = render(STABILITY_CAUSES[st.cause] ?? '', TABLE);
  // V is above the bound at some sample, so at a first one.
  const first = /** @type {number} */ (st.first_outside);
  return `${head}V is above the bound at ${st.outside} of ${st.samples} samples, first at t = ${Number(first.toPrecision(6))} s; ${st.outside_saturated} of them with the voltage saturated (${st.saturated} samples are saturated in all). ${why}`;
}

/**
 * The runs of one scenario with each predictor (`results`), as a sentence and a table.
 * @param {import('../worker/protocol.js').Compared['results']} results
 */
export function comparison(results) {
  const rows = [
    [
      'predictor',
      'tracking RMS (rad/s)',
      'speed-estimate RMS (rad/s)',
      'flux-estimate RMS (Wb)',
      'mean NIS',
      'samples at the voltage limit',
    ],
  ];
  for (const r of results) {
    const m = r.metrics;
    // The core gives no metrics for a run that recorded nothing.
    if (!m) throw new Error(`the ${r.predictor} run recorded nothing`);
    rows.push([
      r.predictor,
      m.tracking_rms.toPrecision(3),
      m.speed_estimate_error_rms.toPrecision(3),
      m.flux_estimate_error_rms.toPrecision(3),
      m.mean_nis.toPrecision(3),
      percent(m.saturated_share),
    ]);
  }
  // The first row names the columns, the first column the predictor.
  /**
   * @param {string} text
   * @param {number} i
   * @param {number} j
   */
  const cell = (text, i, j) =>
    i === 0 || j === 0
      ? el('th', { scope: i === 0 ? 'col' : 'row', textContent: text })
      : el('td', { textContent: text });
  const table = el(
    'table',
    {},
    rows.map((r, i) =>
      el(
        'tr',
        {},
        r.map((c, j) => cell(c, i, j)),
      ),
    ),
  );
  // Every run's metrics are there, as the rows above found.
  return [
    el('p', {
      textContent: `Same scenario and seed, only the EKF predictor differs; figures from t = ${/** @type {Metrics} */ (results[0].metrics).transient_end.toPrecision(3)} s on, the end of the start-up transient, as in the figures strip.`,
    }),
    table,
  ];
}
