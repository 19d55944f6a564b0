// Analysis tab: frequency-response sweeps and seed sweeps run as independent jobs on a pool of
// workers (one per core); every figure is computed by the core in those workers.
import uPlot from '../../vendor/uPlot.esm.js';
import { excerpt } from '../ui/quote.js';
import { el } from '../ui/dom.js';
import { Pool } from '../client/pool.js';
import { fittedRange } from '../plots/ranges.js';
import { pageNumbers } from '../plots/numbers.js';

// Variants offered for the sweep: the field changes that make each from the current scenario.
export const VARIANTS = {
  euler: {
    label: 'Backstepping + Euler EKF (paper)',
    changes: [
      ['controller', 'backstepping'],
      ['perfect', '0'],
      ['ekf', 'euler'],
    ],
  },
  rk4: {
    label: 'Backstepping + RK4 EKF',
    changes: [
      ['controller', 'backstepping'],
      ['perfect', '0'],
      ['ekf', 'rk4'],
    ],
  },
  perfect: {
    label: 'Backstepping + perfect observer',
    changes: [
      ['controller', 'backstepping'],
      ['perfect', '1'],
    ],
  },
  delay: {
    label: 'Backstepping + Euler EKF, one-sample delay',
    changes: [
      ['controller', 'backstepping'],
      ['perfect', '0'],
      ['ekf', 'euler'],
      ['delay', '1'],
      ['delay.comp', '0'],
    ],
  },
  // The like-for-like baseline feeds the reference's torque forward, as the backstepping feeds
  // ω̇_d forward; `ifocpi` is the plain PI speed loop.
  ifoc: {
    label: 'Classical IFOC + MRAS, torque feedforward',
    changes: [
      ['controller', 'ifoc'],
      ['perfect', '0'],
      ['ifoc.ff', '1'],
    ],
  },
  ifocpi: {
    label: 'Classical IFOC + MRAS, no feedforward',
    changes: [
      ['controller', 'ifoc'],
      ['perfect', '0'],
      ['ifoc.ff', '0'],
    ],
  },
};
const COLORS = {
  euler: '#d62728',
  rk4: '#1f77b4',
  perfect: '#2ca02c',
  delay: '#ff7f0e',
  ifoc: '#9467bd',
  ifocpi: '#8c564b',
};

/**
 * Whether `n` can be a number of points: the core takes it as a 32-bit integer, and the
 * conversion would silently truncate 2.5 to 2 or wrap 2^32 + 5 to 5. The core checks the range.
 */
export function isCount(n) {
  return Number.isInteger(n) && n >= 0 && n < 2 ** 32;
}

const SWEEP_KEYS = ['lo', 'hi', 'n', 'amp', 'offset', 'duration'];

/**
 * Sweep settings as written in the URL fragment: `sweep=lo,hi,n,amp,offset,duration,v1.v2`.
 * Throws a short message naming the first part that is not acceptable.
 */
export function parseSweep(text) {
  const parts = text.split(',');
  if (parts.length !== 7) throw new Error(`expected 7 parts lo,hi,n,amp,offset,duration,variants, not ${parts.length}`);
  const settings = {};
  for (const [i, key] of SWEEP_KEYS.entries()) {
    const value = Number(parts[i]);
    if (parts[i].trim() === '' || !Number.isFinite(value))
      throw new Error(`${key} = '${excerpt(parts[i])}' is not a number`);
    settings[key] = value;
  }
  if (!isCount(settings.n)) throw new Error(`n = ${excerpt(parts[2])}: expected a whole number of points`);
  settings.variants = parts[6].split('.');
  const unknown = settings.variants.find((v) => !Object.hasOwn(VARIANTS, v));
  if (unknown !== undefined)
    throw new Error(`variant '${excerpt(unknown)}' is unknown (expected ${Object.keys(VARIANTS).join(', ')})`);
  return settings;
}

export function formatSweep(s) {
  return [s.lo, s.hi, s.n, s.amp, s.offset, s.duration, s.variants.join('.')].join(',');
}

/**
 * Bode plot of `series` ([label, color, values, dash, unsettled]); a series of unsettled points
 * is drawn as hollow markers without a line.
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
  return [opts, data];
}

/**
 * The table cell of the largest stator current |i_s| a variant's points need (each over its fit
 * window, from the core), against the scenario's rated current; the points above the rating are
 * listed and the cell is marked.
 */
function peakCell(points) {
  const measured = points.filter((p) => !p.failure);
  if (!measured.length) return el('td', { textContent: 'none measured' });
  const peak = Math.max(...measured.map((p) => p.peak_current));
  const rated = measured[0].rated_current;
  const above = measured.filter((p) => p.peak_current > p.rated_current).map((p) => `${p.freq.toPrecision(4)} Hz`);
  const text = `${peak.toPrecision(3)} (rated ${rated.toPrecision(3)})`;
  return above.length
    ? el('td', {
        className: 'over-rating',
        textContent: `${text}; above the rating at ${above.length}: ${above.join(', ')}`,
      })
    : el('td', { textContent: text });
}

export class Analysis {
  constructor({ scenario }) {
    this.scenario = scenario;
    this.pool = new Pool(Math.max(1, Math.min(4, navigator.hardwareConcurrency || 2)));
    this.points = {};
  }

  /**
   * Runs a sweep of the current scenario; resolves with {variant: {points, summary}}.
   * @param {any} settings
   * @param {{onProgress?: (share: number) => void, workers?: number}} [options]
   */
  async sweep(settings, { onProgress = () => {}, workers } = {}) {
    if (workers) this.pool.size = workers;
    const [freqs] = await this.pool.run([{ kind: 'grid', lo: settings.lo, hi: settings.hi, n: settings.n }]);
    const jobs = settings.variants.flatMap((v) =>
      freqs.map((freq) => ({
        kind: 'sweep',
        scenario: this.scenario(),
        changes: VARIANTS[v].changes,
        freq,
        amp: settings.amp,
        duration: settings.duration,
        offset: settings.offset,
      })),
    );
    const results = await this.pool.run(jobs, (done) => onProgress(done / jobs.length));
    const out = {};
    for (const [i, v] of settings.variants.entries()) {
      const points = results.slice(i * freqs.length, (i + 1) * freqs.length);
      const [summary] = await this.pool.run([{ kind: 'summary', points }]);
      out[v] = { points, summary };
    }
    this.points = out;
    return out;
  }

  async sweepCsv(variant) {
    const [csv] = await this.pool.run([{ kind: 'sweep-csv', points: this.points[variant].points }]);
    return csv;
  }

  showSweep(out, bodeBox, table) {
    const variants = Object.keys(out);
    const freqs = out[variants[0]].points.map((p) => p.freq);
    // Failed points are gaps (null), never drawn; unsettled points are drawn apart, as hollow
    // markers, and left out of the line.
    const column = (v, key, unsettled) =>
      out[v].points.map((p) => (p.failure || Boolean(p.unsettled) !== unsettled ? null : p[key]));
    const flagged = variants.flatMap((v) => out[v].points.filter((p) => p.unsettled).map((p) => [v, p]));
    bodeBox.replaceChildren();
    if (flagged.length) {
      bodeBox.append(
        el('details', { className: 'sweep-unsettled' }, [
          el('summary', {
            textContent: `${flagged.length} point${flagged.length > 1 ? 's' : ''} had not settled (hollow markers): the bandwidth and the phase at 200 Hz are never read off them. Longer runs may settle them.`,
          }),
          el(
            'ul',
            {},
            flagged.map(([v, p]) =>
              el('li', { textContent: `${VARIANTS[v].label}, ${p.freq.toPrecision(4)} Hz: ${p.unsettled}` }),
            ),
          ),
        ]),
      );
    }
    const width = Math.max(400, bodeBox.clientWidth - 10);
    // Dashed lines for variants drawn on top of others, so overlapping curves stay visible.
    const dash = { rk4: [6, 4], perfect: [2, 3], ifocpi: [6, 4] };
    for (const [title, unit, key, marker] of [
      ['Magnitude of ω/ω_d', 'dB', 'gain_db', ['−3 dB', -3]],
      ['Phase of ω against ω_d', 'degrees', 'phase', null],
    ]) {
      const series = variants.flatMap((v) => [
        [VARIANTS[v].label, COLORS[v], column(v, key, false), dash[v]],
        ...(out[v].summary.unsettled
          ? [[`${VARIANTS[v].label}, not settled`, COLORS[v], column(v, key, true), null, true]]
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
          'variant',
          '−3 dB bandwidth',
          'phase at 200 Hz',
          'worst saturation',
          'failed points',
          'unsettled points',
          'peak |i_s| (A)',
        ].map((h) => el('th', { textContent: h })),
      ),
    );
    for (const v of variants) {
      const { points, summary } = out[v];
      const fmt = (x, unit, missing) => (x == null ? missing : `${x.toPrecision(4)} ${unit}`);
      const worst = Math.max(...points.map((p) => (p.failure ? 0 : p.saturated)));
      const bandwidth = summary.bandwidth_unsettled
        ? 'not given: it would rest on a point that had not settled'
        : summary.below_grid
          ? 'below the lowest frequency'
          : fmt(summary.bandwidth, 'Hz', 'not reached in the grid');
      // The phase is interpolated between settled points only.
      const phase = fmt(
        summary.phase_at_200,
        '°',
        summary.unsettled ? 'not reached by the settled points' : 'not reached in the grid',
      );
      const unsettled = points.filter((p) => p.unsettled).map((p) => `${p.freq.toPrecision(4)} Hz`);
      const row = el(
        'tr',
        {},
        [
          VARIANTS[v].label,
          bandwidth,
          phase,
          `${worst.toPrecision(3)} of samples`,
          String(points.filter((p) => p.failure).length),
          unsettled.length ? `${unsettled.length}: ${unsettled.join(', ')}` : '0',
        ].map((c) => el('td', { textContent: c })),
      );
      row.append(peakCell(points));
      row.dataset.variant = v;
      table.append(row);
    }
  }

  /**
   * Runs `n` seeds from `first`; resolves with {results, bands}. The core gives the seeds, and
   * refuses a range past the largest seed before any run.
   */
  async seeds(n, first, steps, onProgress = /** @type {(share: number) => void} */ (() => {})) {
    const every = Math.max(1, Math.floor(steps / 1000));
    const [seeds] = await this.pool.run([{ kind: 'seed-range', first, n }]);
    const jobs = seeds.map((seed) => ({ kind: 'seed', scenario: this.scenario(), seed, every }));
    const runs = await this.pool.run(jobs, (done) => onProgress(done / n));
    const [bands] = await this.pool.run([{ kind: 'bands', runs }]);
    const [csv] = await this.pool.run([{ kind: 'seeds-csv', results: runs.map((r) => r.result) }]);
    return { results: runs.map((r) => r.result), bands, csv };
  }

  /** Draws the seed bands; with `framing().fit` the y-axes leave out t < framing().from. */
  showSeeds({ bands }, box, framing) {
    box.replaceChildren();
    // The y range over the samples after the start-up transient (all of them when framing is off).
    /** @type {uPlot.Range.Function} */
    const range = (u, _min, _max, key) => fittedRange(u, key, false, framing());
    this.seedCharts = [];
    // The same colours as ω − ω_d and ω − ω̂ on the Trajectories tab.
    for (const [title, b, color] of [
      ['Speed error ω − ω_d over seeds (mean, min, max)', bands.error, '#d62728'],
      ['Estimation error ω − ω̂ over seeds (mean, min, max)', bands.estimate, '#8c564b'],
    ]) {
      /** @type {uPlot.Options} */
      const opts = {
        title,
        width: Math.max(320, box.clientWidth - 10),
        height: 240,
        scales: { x: { time: false }, y: { range } },
        series: [
          { label: 't (s)' },
          { label: 'mean', stroke: color, width: 2 },
          { label: 'min', stroke: '#8a8a8a', dash: [3, 3] },
          { label: 'max', stroke: '#8a8a8a', dash: [3, 3] },
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
