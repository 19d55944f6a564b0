// What a run's results say in the walkthrough: the stability report (V against its bound) and the
// table comparing the Euler and RK4 predictors. The figures come from the core; this formats them
// in the words of the walkthrough's messages.
import { FluentNumber } from '@fluent/bundle';
import { el } from '../ui/dom.js';
import { t } from '../l10n/l10n.js';
import { percent } from '../plots/numbers.js';
import { STABILITY_CAUSES } from './walkthrough-text.js';
import { decimal, measured } from './walkthrough-sections.js';

/**
 * The metrics of a finished run that recorded something.
 * @typedef {NonNullable<import('../worker/protocol.js').Compared['results'][number]['metrics']>} Metrics
 */

/**
 * The stability report `st` of a run, in words.
 * @param {import('../worker/protocol.js').Done['stability']} st
 */
export function stabilityText(st) {
  if (!st) return t('walkthrough-stability-nothing');
  const b = st.bound;
  const bound = { lambda: decimal(String(b.lambda)), eps: decimal(String(b.eps)) };
  const head = t(b.eps ? 'walkthrough-stability-bound-robust' : 'walkthrough-stability-bound-off', bound);
  if (st.outside === 0) return `${head} ${t('walkthrough-stability-under', { samples: count(st.samples) })}`;
  const cause = STABILITY_CAUSES[st.cause];
  const why = cause ? measured(cause) : '';
  // V is above the bound at some sample, so at a first one.
  const first = /** @type {number} */ (st.first_outside);
  const above = t('walkthrough-stability-above', {
    outside: count(st.outside),
    samples: count(st.samples),
    first: decimal(String(Number(first.toPrecision(6)))),
    outsideSaturated: count(st.outside_saturated),
    saturated: count(st.saturated),
  });
  return `${head} ${above} ${why}`;
}

/**
 * A count of samples as the report writes it, digits ungrouped, and as a number for the plural.
 * @param {number} n
 */
const count = (n) => new FluentNumber(n, { useGrouping: false });

/**
 * The runs of one scenario with each predictor (`results`), as a sentence and a table.
 * @param {import('../worker/protocol.js').Compared['results']} results
 */
export function comparison(results) {
  const rows = [
    [
      t('walkthrough-compare-predictor'),
      t('walkthrough-compare-tracking'),
      t('walkthrough-compare-speed'),
      t('walkthrough-compare-flux'),
      t('walkthrough-compare-nis'),
      t('walkthrough-compare-saturated'),
    ],
  ];
  for (const r of results) {
    const m = r.metrics;
    // The core gives no metrics for a run that recorded nothing.
    if (!m) throw new Error(`the ${r.predictor} run recorded nothing`);
    rows.push([
      r.predictor,
      decimal(m.tracking_rms.toPrecision(3)),
      decimal(m.speed_estimate_error_rms.toPrecision(3)),
      decimal(m.flux_estimate_error_rms.toPrecision(3)),
      decimal(m.mean_nis.toPrecision(3)),
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
      textContent: t('walkthrough-compare-note', {
        from: decimal(/** @type {Metrics} */ (results[0].metrics).transient_end.toPrecision(3)),
      }),
    }),
    table,
  ];
}
