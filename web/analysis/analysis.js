// Analysis tab: frequency-response sweeps and seed sweeps run as independent jobs on a pool of
// workers (one per core); every figure is computed by the core in those workers.
import uPlot from '../../vendor/uPlot.esm.js';
import { el } from '../ui/dom.js';
import { Pool } from '../client/pool.js';
import { fittedRange } from '../plots/ranges.js';
import { pageNumbers, percent } from '../plots/numbers.js';
import { t } from '../l10n/l10n.js';
import { integer, precise } from './digits.js';

/** @import * as P from '../worker/protocol.js' */
/** @typedef {P.Jobs['sweep-plan']['result']} PlanView */
/** @typedef {P.Jobs['sweep']['result']} SweepPoint */
/** @typedef {P.Jobs['summary']['result']} SweepSummary */
/** @typedef {{label: string, points: SweepPoint[], summary: SweepSummary}} VariantSweep */

// Each variant's colour on the Bode plots, by its name in the core's plan.
/** @type {Record<string, string>} */
const COLORS = {
  euler: '#d62728',
  rk4: '#1f77b4',
  perfect: '#2ca02c',
  delay: '#ff7f0e',
  ifoc: '#9467bd',
  ifocpi: '#8c564b',
};

/**
 * A series of a Bode plot: its label, colour, values (null where a point is not drawn), dash,
 * and whether it holds unsettled points.
 * @typedef {[string, string, (number | null)[], number[] | undefined, boolean?]} BodeSeries
 */

/**
 * Bode plot of `series`; a series of unsettled points is drawn as hollow markers without a line.
 * @param {string} title
 * @param {string} unit
 * @param {number[]} freqs
 * @param {BodeSeries[]} series
 * @param {number} width
 * @param {[string, number] | null} marker
 * @returns {[uPlot.Options, uPlot.AlignedData]}
 */
function bodePlot(title, unit, freqs, series, width, marker) {
  /** @type {uPlot.Options} */
  const opts = {
    title,
    width,
    height: 280,
    scales: { x: { time: false, distr: 3, log: 10 } },
    series: [
      { label: 'f (Hz)' },
      ...series.map(([label, color, , dash, unsettled]) =>
        unsettled
          ? { label, stroke: color, width: 2, paths: () => null, points: { show: true, size: 10, fill: '#fff' } }
          : { label, stroke: color, dash, width: 2, points: { show: true } },
      ),
    ],
    axes: [{ label: 'f (Hz)' }, { label: unit, size: 70 }],
  };
  const data = [freqs, ...series.map((s) => s[2])];
  if (marker) {
    opts.series.push({ label: marker[0], stroke: '#999', dash: [4, 4], width: 1.5 });
    data.push(freqs.map(() => marker[1]));
  }
  return [opts, /** @type {uPlot.AlignedData} */ (data)];
}

/**
 * The table cell of the largest stator current |i_s| a variant's points need (each over its fit
 * window), against the scenario's rated current, with the points above the rating listed and the
 * cell marked: every figure from the core's summary.
 * @param {SweepSummary} summary
 */
function peakCell({ peak_current: peak, rated_current: rated, over_rating: above }) {
  if (peak === null || rated === null) return el('td', { textContent: t('sweep-peak-none') });
  const args = { peak: precise(peak, 3), rated: precise(rated, 3) };
  return above.length
    ? el('td', {
        className: 'over-rating',
        textContent: t('sweep-peak-over', {
          ...args,
          count: integer(above.length),
          frequencies: above.map(hz).join(', '),
        }),
      })
    : el('td', { textContent: t('sweep-peak', args) });
}

/** @param {number} f */
const hz = (f) => t('sweep-hz', { value: precise(f, 4) });

export class Analysis {
  /**
   * `scenario()` is the current scenario's text; `client` the run worker, which reads a sweep's
   * plan without touching the pool's jobs.
   * @param {{scenario: () => string, client: import('../client/run-client.js').RunClient}} parts
   */
  constructor({ scenario, client }) {
    this.scenario = scenario;
    this.client = client;
    this.pool = new Pool(Math.max(1, Math.min(4, navigator.hardwareConcurrency || 2)));
    /** @type {Record<string, VariantSweep>} */
    this.points = {};
    /** @type {uPlot[]} */
    this.seedCharts = [];
  }

  /**
   * A sweep's plan read by the core from its text (a link's `#sweep=`); rejects with the message
   * naming the first part that is not acceptable.
   * @param {string} text
   * @returns {Promise<PlanView>}
   */
  plan(text) {
    return this.client.job('sweep-plan', { text });
  }

  /**
   * A sweep's plan from a form's parts as written, checked by the core as a link's would be.
   * @param {string[]} numbers lo, hi, n, amp, offset, duration
   * @param {string[]} variants
   * @returns {Promise<PlanView>}
   */
  planOf(numbers, variants) {
    return this.client.job('sweep-plan-of', { numbers, variants });
  }

  /**
   * Runs the sweep `view` plans of `scenario` (the current one unless given); resolves with each
   * variant's points and summary, by its name.
   * @param {PlanView} view
   * @param {{onProgress?: (share: number) => void, workers?: number, scenario?: string}} [options]
   */
  async sweep({ plan, frequencies, labels }, { onProgress = () => {}, workers, scenario = this.scenario() } = {}) {
    if (workers) this.pool.size = workers;
    const jobs = plan.variants.flatMap((variant) =>
      frequencies.map((freq) => ({
        kind: /** @type {const} */ ('sweep'),
        scenario,
        variant,
        freq,
        amp: plan.amp,
        duration: plan.duration,
        offset: plan.offset,
      })),
    );
    const results = /** @type {SweepPoint[]} */ (await this.pool.run(jobs, (done) => onProgress(done / jobs.length)));
    /** @type {Record<string, VariantSweep>} */
    const out = {};
    for (const [i, v] of plan.variants.entries()) {
      const points = results.slice(i * frequencies.length, (i + 1) * frequencies.length);
      const [summary] = await this.pool.run([{ kind: 'summary', points }]);
      out[v] = { label: labels[i], points, summary: /** @type {SweepSummary} */ (summary) };
    }
    this.points = out;
    return out;
  }

  /** @param {string} variant */
  async sweepCsv(variant) {
    const [csv] = await this.pool.run([{ kind: 'sweep-csv', points: this.points[variant].points }]);
    return /** @type {string} */ (csv);
  }

  /**
   * Draws a sweep's Bode plots in `bodeBox` and its summary in `table`.
   * @param {Record<string, VariantSweep>} out
   * @param {HTMLElement} bodeBox
   * @param {HTMLTableElement} table
   */
  showSweep(out, bodeBox, table) {
    const variants = Object.keys(out);
    const freqs = out[variants[0]].points.map((p) => p.freq);
    // Failed points are gaps (null), never drawn; unsettled points are drawn apart, as hollow
    // markers, and left out of the line.
    /**
     * @param {string} v
     * @param {'gain_db' | 'phase'} key
     * @param {boolean} unsettled
     */
    const column = (v, key, unsettled) =>
      out[v].points.map((p) => (p.failure || Boolean(p.unsettled) !== unsettled ? null : p[key]));
    const flagged = variants.flatMap((v) => out[v].points.filter((p) => p.unsettled).map((p) => ({ v, p })));
    bodeBox.replaceChildren();
    if (flagged.length) {
      bodeBox.append(
        el('details', { className: 'sweep-unsettled' }, [
          el('summary', {
            textContent: t('sweep-unsettled', { count: integer(flagged.length) }),
          }),
          el(
            'ul',
            {},
            flagged.map(({ v, p }) =>
              el('li', {
                textContent: t('sweep-unsettled-point', {
                  variant: out[v].label,
                  frequency: hz(p.freq),
                  reason: String(p.unsettled),
                }),
              }),
            ),
          ),
        ]),
      );
    }
    const width = Math.max(400, bodeBox.clientWidth - 10);
    // Dashed lines for variants drawn on top of others, so overlapping curves stay visible.
    /** @type {Record<string, number[]>} */
    const dash = { rk4: [6, 4], perfect: [2, 3], ifocpi: [6, 4] };
    /** @type {[string, string, 'gain_db' | 'phase', [string, number] | null][]} */
    const plots = [
      [t('sweep-plot-magnitude'), 'dB', 'gain_db', ['−3 dB', -3]],
      [t('sweep-plot-phase'), t('sweep-axis-degrees'), 'phase', null],
    ];
    for (const [title, unit, key, marker] of plots) {
      const series = variants.flatMap((v) => [
        /** @type {BodeSeries} */ ([out[v].label, COLORS[v], column(v, key, false), dash[v]]),
        ...(out[v].summary.unsettled
          ? [
              /** @type {BodeSeries} */ ([
                t('sweep-series-unsettled', { variant: out[v].label }),
                COLORS[v],
                column(v, key, true),
                undefined,
                true,
              ]),
            ]
          : []),
      ]);
      const [opts, data] = bodePlot(title, unit, freqs, series, width, marker);
      const div = el('div', { className: 'plot' });
      bodeBox.append(div);
      new uPlot(pageNumbers(opts), data, div);
    }
    table.replaceChildren(
      el(
        'tr',
        {},
        [
          'sweep-head-variant',
          'sweep-head-bandwidth',
          'sweep-head-phase',
          'sweep-head-saturation',
          'sweep-head-failed',
          'sweep-head-unsettled',
          'sweep-head-peak',
        ].map((h) => el('th', { textContent: t(h) })),
      ),
    );
    for (const v of variants) {
      const { points, summary, label } = out[v];
      /**
       * @param {number | null} x
       * @param {string} id the message writing `x` with its unit
       * @param {string} missing the message saying why there is no `x`
       */
      const fmt = (x, id, missing) => (x == null ? t(missing) : t(id, { value: precise(x, 4) }));
      const bandwidth = summary.bandwidth_unsettled
        ? t('sweep-bandwidth-unsettled')
        : summary.below_grid
          ? t('sweep-bandwidth-below')
          : fmt(summary.bandwidth, 'sweep-hz', 'sweep-not-reached');
      // The phase is interpolated between settled points only.
      const phase = fmt(
        summary.phase_at_200,
        'sweep-degrees',
        summary.unsettled ? 'sweep-phase-not-reached-settled' : 'sweep-not-reached',
      );
      const unsettled = points.filter((p) => p.unsettled).map((p) => hz(p.freq));
      const row = el(
        'tr',
        {},
        [
          label,
          bandwidth,
          phase,
          // None when no point ran: nothing to say, not 0 %.
          summary.worst_saturation === null ? '–' : percent(summary.worst_saturation),
          String(summary.failed),
          unsettled.length
            ? t('sweep-unsettled-cell', { count: integer(unsettled.length), frequencies: unsettled.join(', ') })
            : '0',
        ].map((c) => el('td', { textContent: c })),
      );
      row.append(peakCell(summary));
      row.dataset.variant = v;
      table.append(row);
    }
  }

  /**
   * Runs `scenario` with `n` seeds from `first`; resolves with {results, bands}. The core gives the
   * seeds, and refuses a range past the largest seed before any run.
   * @param {string} scenario
   * @param {number} n
   * @param {number} first
   * @param {number} steps the scenario's steps, of which about 1000 are kept
   * @param {(share: number) => void} [onProgress]
   */
  async seeds(scenario, n, first, steps, onProgress = () => {}) {
    const every = Math.max(1, Math.floor(steps / 1000));
    const [seeds] = await this.pool.run([{ kind: 'seed-range', first, n }]);
    const jobs = seeds.map((seed) => ({ kind: /** @type {const} */ ('seed'), scenario, seed, every }));
    const runs = await this.pool.run(jobs, (done) => onProgress(done / n));
    const [bands] = await this.pool.run([{ kind: 'bands', runs }]);
    const [csv] = await this.pool.run([{ kind: 'seeds-csv', results: runs.map((r) => r.result) }]);
    return { results: runs.map((r) => r.result), bands, csv };
  }

  /**
   * Draws the seed bands; with `framing().fit` the y-axes leave out t < framing().from.
   * @param {{bands: P.Jobs['bands']['result']}} seeds
   * @param {HTMLElement} box
   * @param {() => {fit: boolean, from: number}} framing
   */
  showSeeds({ bands }, box, framing) {
    box.replaceChildren();
    // The y range over the samples after the start-up transient (all of them when framing is off).
    /** @type {uPlot.Range.Function} */
    const range = (u, _min, _max, key) => fittedRange(u, key, false, framing());
    this.seedCharts = [];
    // The same colours as ω − ω_d and ω − ω̂ on the Trajectories tab.
    /** @type {[string, P.Jobs['bands']['result']['error'], string][]} */
    const plots = [
      [t('seeds-plot-error'), bands.error, '#d62728'],
      [t('seeds-plot-estimate'), bands.estimate, '#8c564b'],
    ];
    for (const [title, b, color] of plots) {
      /** @type {uPlot.Options} */
      const opts = {
        title,
        width: Math.max(320, box.clientWidth - 10),
        height: 240,
        scales: { x: { time: false }, y: { range } },
        series: [
          { label: 't (s)' },
          { label: t('seeds-series-mean'), stroke: color, width: 2 },
          { label: t('seeds-series-min'), stroke: '#8a8a8a', dash: [3, 3] },
          { label: t('seeds-series-max'), stroke: '#8a8a8a', dash: [3, 3] },
        ],
        bands: [{ series: /** @type {uPlot.Band.Bounds} */ ([3, 2]), fill: 'rgba(31,119,180,0.15)' }],
        axes: [{ label: 't (s)' }, { label: 'rad/s', size: 70 }],
      };
      const div = el('div', { className: 'plot' });
      box.append(div);
      this.seedCharts.push(new uPlot(pageNumbers(opts), [bands.t, b.mean, b.min, b.max], div));
    }
  }

  /** Re-fits the seed plots' y-axes (after the framing changed). */
  refit() {
    for (const c of this.seedCharts ?? []) c.setData(c.data, true);
  }
}
