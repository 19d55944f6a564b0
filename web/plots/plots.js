// The trajectory plots: uPlot charts with a shared, synchronised time axis.
// Each plot draws the M4 envelope the worker sends for its own columns: every point is a recorded
// sample at its own time, so no zoom draws an edge the samples do not have.
import uPlot from '../../vendor/uPlot.esm.js';

// One visual language in every tab: a signal has the same colour and dash wherever it is drawn.
// References and bands are dashed grey, true signals blue, estimates orange (b-axis components
// a darker shade of the same colour).
const REFERENCE = { stroke: '#6b6b6b', dash: [6, 4] };
const BAND = { stroke: '#8a8a8a', dash: [3, 3] };
const STYLE = {
  omega_ref: REFERENCE,
  flux_ref: REFERENCE,
  omega: { stroke: '#1f77b4' },
  flux: { stroke: '#1f77b4' },
  i_sa: { stroke: '#1f77b4' },
  i_sb: { stroke: '#0b3d6e' },
  omega_hat: { stroke: '#ff7f0e' },
  flux_hat: { stroke: '#ff7f0e' },
  i_sa_hat: { stroke: '#ff7f0e' },
  i_sb_hat: { stroke: '#a34a00' },
  u_a: { stroke: '#2ca02c' },
  u_b: { stroke: '#135f13' },
  u_a_cmd: { stroke: '#9467bd' },
  omega_err: { stroke: '#d62728' },
  omega_est_err: { stroke: '#8c564b' },
  flux_est_err: { stroke: '#bcbd22' },
  z1: { stroke: '#e377c2' },
  z2: { stroke: '#17becf' },
  z3: { stroke: '#7b4173' },
  z4: { stroke: '#e7969c' },
  v1: { stroke: '#333333' },
  v2: { stroke: '#333333' },
  v3: { stroke: '#333333' },
  v4: { stroke: '#333333' },
  v1a: { stroke: '#9467bd' },
  v2a: { stroke: '#9467bd' },
  v3a: { stroke: '#9467bd' },
  v4a: { stroke: '#9467bd' },
  v1s: { stroke: '#2ca02c' },
  v2s: { stroke: '#2ca02c' },
  v3s: { stroke: '#2ca02c' },
  v4s: { stroke: '#2ca02c' },
  torque_hat: { stroke: '#ff7f0e' },
  innov_a: { stroke: '#9467bd' },
  innov_band_a: BAND,
  nis: { stroke: '#9467bd' },
  p_omega: { stroke: '#8c564b' },
  lyapunov: { stroke: '#d62728' },
  lyapunov_bound: BAND,
  load_hat: { stroke: '#ff7f0e' },
  load: { stroke: '#1f77b4' },
  load_band: BAND,
  rr_hat: { stroke: '#ff7f0e' },
  rr: { stroke: '#1f77b4' },
  rr_band: BAND,
};
const CONSTANT = BAND;

// Each plot: [column, label, axis, sign, about]; axis 'y2' puts a series on the right-hand scale,
// sign −1 draws the column negated (the lower half of a ±band), and `about` adds the column to
// another (an estimate ± its band). Later series are drawn on top, so the true signals come after
// their estimates and stay visible.
export const PLOTS = [
  {
    id: 'speed',
    title: 'Rotor speed',
    unit: 'rad/s',
    series: [
      ['omega_ref', 'ω_d reference'],
      ['omega_hat', 'ω̂ estimated'],
      ['omega', 'ω true'],
    ],
  },
  {
    id: 'speed-error',
    title: 'Speed tracking error ω − ω_d',
    unit: 'rad/s',
    series: [['omega_err', 'ω − ω_d']],
  },
  {
    id: 'flux',
    title: 'Rotor-flux modulus',
    unit: 'Wb',
    series: [
      ['flux_ref', '√ψ_d target'],
      ['flux_hat', '|φ̂| estimated'],
      ['flux', '|φ| true'],
    ],
  },
  {
    id: 'current',
    title: 'Stator currents',
    unit: 'A',
    series: [
      ['i_sa_hat', 'î_sa estimated'],
      ['i_sb_hat', 'î_sb estimated'],
      ['i_sa', 'i_sa true'],
      ['i_sb', 'i_sb true'],
    ],
  },
  {
    id: 'voltage',
    title: 'Applied stator voltages (after the limit)',
    unit: 'V',
    constants: [['+limit'], ['−limit']],
    series: [
      ['u_a', 'u_sa'],
      ['u_b', 'u_sb'],
    ],
  },
  {
    id: 'z13',
    title: 'Tracking errors',
    unit: 'rad/s',
    unit2: 'Wb²',
    backstepping: true,
    series: [
      ['z1', 'z1 = ω̂ − ω_d (rad/s)'],
      ['z3', 'z3 = |φ̂|² − ψ_d (Wb², right)', 'y2'],
    ],
  },
  {
    id: 'z24',
    title: 'Virtual-control errors',
    unit: 'rad/s²',
    unit2: 'Wb²/s',
    backstepping: true,
    series: [
      ['z2', 'z2 torque error (rad/s²)'],
      ['z4', 'z4 flux-rate error (Wb²/s, right)', 'y2'],
    ],
  },
  {
    id: 'est',
    title: 'Estimation errors',
    unit: 'rad/s',
    unit2: 'Wb',
    series: [
      ['omega_est_err', 'ω − ω̂ (rad/s)'],
      ['flux_est_err', '|φ| − |φ̂| (Wb, right)', 'y2'],
    ],
  },
];

/** The backstepping plots' title suffix when the IFOC baseline drives the motor. */
const NOT_DRIVING = ' (computed for comparison; not driving the motor)';

const SYNC_KEY = 'imlab-time';

// A log axis spanning whole decades (uPlot's log splits need them), at most 14 below the maximum.
function logRange(u, min, max) {
  const top = Math.ceil(Math.log10(max));
  const bottom = Math.max(Math.floor(Math.log10(min)), top - 14);
  return [10 ** bottom, 10 ** top];
}

// Tick steps of 1, 2 and 5 times a power of ten: a step of 2.5 would cost every label one more digit.
const STEPS = Array.from({ length: 33 }, (_, i) => i - 16).flatMap((e) => [1, 2, 5].map((m) => Number(`${m}e${e}`)));

/** Decimals that write `step` exactly (0.25 needs 2, 200 needs none). */
function decimals(step) {
  for (let d = 0; d < 20; d++) {
    const m = step * 10 ** d;
    if (Math.round(m) >= 1 && Math.abs(m - Math.round(m)) < 1e-6 * m) return d;
  }
  return 20;
}

// Values this far from 1 read better as powers of ten than as long runs of zeros.
const SMALL = 1e-3;
const LARGE = 1e6;

/**
 * Tick labels with the digits their spacing needs, so that neighbouring ticks never read alike
 * at any zoom; tiny and huge values as powers of ten. A log axis's ticks are each one digit times
 * a power of ten, so three significant digits write every one of them.
 */
function tickLabels(u, splits, axisIdx, space, step) {
  if (u.scales[u.axes[axisIdx].scale].distr === 3 || !(step > 0)) {
    return splits.map((v) => (v == null ? '' : String(Number(v.toPrecision(3)))));
  }
  // A tick that should be zero often misses it by a rounding error, which would print as −0.
  const ticks = splits.map((v) => (v == null ? null : Math.abs(v) < step * 1e-6 ? 0 : v));
  const largest = Math.max(...ticks.map((v) => Math.abs(v ?? 0)));
  const d = decimals(step);
  if (largest === 0 || (largest >= SMALL && largest < LARGE)) return ticks.map((v) => (v == null ? '' : v.toFixed(d)));
  return ticks.map((v) => {
    if (v == null) return '';
    if (v === 0) return '0';
    const digits = Math.min(Math.max(Math.floor(Math.log10(Math.abs(v))) + d, 0), 20);
    return v
      .toExponential(digits)
      .replace(/\.?0+e/, 'e')
      .replace('e+', 'e');
  });
}

/**
 * The least room between time ticks (px), `least` or more: room for a label with the window's
 * whole digits and the decimals of the finest step `least` allows, and a gap of one `em` (the
 * font size, px), so that the long labels of a narrow window do not run into each other.
 */
const timeSpace = (em, least) => (u, axisIdx, lo, hi, dim) => {
  const step = ((hi - lo) * least) / dim;
  if (!(step > 0)) return least;
  const chars = String(Math.trunc(Math.max(Math.abs(lo), Math.abs(hi)))).length + 1 - Math.floor(Math.log10(step));
  return Math.max(least, (chars * 0.6 + 1) * em);
};

/** A value as the read-out shows it: 6 significant digits. */
export const six = (v) => (v == null ? '–' : String(Number(v.toPrecision(6))));

/** Min and max of the series on `scale` over the samples with t ≥ from (all of them if none). */
function extent(u, scale, from) {
  const t = u.data[0];
  const scan = (start) => {
    let lo = Infinity;
    let hi = -Infinity;
    for (let s = 1; s < u.series.length; s++) {
      if (u.series[s].scale !== scale || !u.series[s].show) continue;
      const y = u.data[s];
      for (let j = 0; j < t.length; j++) {
        if (t[j] < start) continue;
        const v = y[j];
        if (v < lo) lo = v;
        if (v > hi) hi = v;
      }
    }
    return [lo, hi];
  };
  const fitted = scan(from);
  return fitted[0] <= fitted[1] ? fitted : scan(-Infinity);
}

/** [lo, hi] padded by 5 % (a flat signal gets a band of its own size, or ±1 at zero). */
function padded([lo, hi]) {
  if (!(lo <= hi)) return [-1, 1];
  if (lo === hi) {
    const d = Math.abs(lo) * 0.1 || 1;
    return [lo - d, hi + d];
  }
  const d = (hi - lo) * 0.05;
  return [lo - d, hi + d];
}

// Aligning the zeros of two axes may shrink a series to this fraction of the plot's height, no
// less: further, the shared zero line costs more than it shows.
const MIN_SHARE = 0.5;

/**
 * Widens two ranges so that zero sits at the same height on both axes, when both ranges hold zero
 * and neither series shrinks below MIN_SHARE of the height; otherwise returns them as they are.
 * Either range only grows, so each still holds its series.
 */
function shareZero(a, b) {
  const below = ([lo, hi]) => -lo / (hi - lo); // zero's height as a fraction of the axis
  const [fa, fb] = [below(a), below(b)];
  if (!(fa >= 0 && fa <= 1 && fb >= 0 && fb <= 1) || fa === fb) return [a, b];
  const [low, high] = fa < fb ? [a, b] : [b, a]; // the axis with zero lower, and the other
  const [f0, f1] = [Math.min(fa, fb), Math.max(fa, fb)];
  // Either lower the bottom of `low` until its zero is as high as on `high`, or raise the top of
  // `high` until its zero is as low as on `low`: whichever shrinks its series less.
  const lowered = f1 < 1 ? (1 - f0) / (1 - f1) : Infinity;
  const raised = f0 > 0 ? f1 / f0 : Infinity;
  if (Math.min(lowered, raised) > 1 / MIN_SHARE) return [a, b];
  const aligned =
    lowered <= raised
      ? [[Math.min(low[0], (-f1 * low[1]) / (1 - f1)), low[1]], high]
      : [low, [high[0], Math.max(high[1], (-high[0] * (1 - f0)) / f0)]];
  return fa < fb ? aligned : [aligned[1], aligned[0]];
}

/**
 * A set of plots sharing the synchronised time axis. `onWindow(t0, t1)` asks for the data of a
 * zoom window, `onFull()` for the whole run, `onPick(t)` inspects a time. `constants(plot)` gives
 * the values of a plot's constant lines (limits, bands), which come from the core. `framing()`
 * says whether the y-axes leave out the start-up transient, and where it ends.
 */
export class Plots {
  /**
   * `onPick(t)` inspects time t (a click, or the arrow keys on a focused plot); `sampleTime()` is
   * the run's Ts, the step of one arrow press.
   */
  constructor(
    container,
    defs,
    { onWindow, onFull, onPick, constants = () => [], framing, height = 260, sampleTime = () => null },
  ) {
    Object.assign(this, { container, defs, onWindow, onFull, onPick, constants, framing, height, sampleTime });
    this.scale = 1; // text and line scale: 1, or larger in presentation mode
    this.captions = ''; // the run's figures, as the captions give them
    this.charts = [];
    this.syncing = false;
    this.full = null; // [t0, t1] of the whole run
    this.window = null; // the zoom window, or null for the whole run
    this.marker = null; // the inspected time
    this.ifoc = false;
  }

  width() {
    return Math.max(280, this.container.clientWidth - 8);
  }

  /** The columns each plot needs, by plot id (the worker sends one envelope per plot). */
  groups() {
    return Object.fromEntries(
      this.defs.map((p) => [p.id, [...new Set(p.series.flatMap((s) => (s[4] ? [s[0], s[4]] : [s[0]])))]]),
    );
  }

  title(plot) {
    return plot.backstepping && this.ifoc ? plot.title + NOT_DRIVING : plot.title;
  }

  options(plot, width) {
    const series = [{ label: 't (s)', value: (u, v) => (v == null ? '–' : `${six(v)} s`) }];
    for (const [column, label, axis] of plot.series) {
      const style = STYLE[column] ?? { stroke: '#444' };
      series.push({
        label,
        scale: axis === 'y2' ? 'y2' : 'y',
        stroke: style.stroke,
        dash: style.dash,
        width: this.scale,
        value: (u, v) => six(v),
      });
    }
    for (const [label, axis] of plot.constants ?? []) {
      series.push({ label, scale: axis ?? 'y', ...CONSTANT, width: this.scale, value: (u, v) => six(v) });
    }
    const k = this.scale;
    const font = { font: `${14 * k}px system-ui`, labelFont: `${14 * k}px system-ui`, labelSize: 24 * k };
    const axes = [
      { label: 't (s)', ...font, size: 50 * k, space: timeSpace(14 * k, 50 * k), incrs: STEPS, values: tickLabels },
      {
        label: plot.unit,
        scale: 'y',
        ...font,
        size: 80 * k,
        ...(plot.log ? {} : { incrs: STEPS }),
        values: tickLabels,
      },
    ];
    if (plot.unit2)
      axes.push({
        label: plot.unit2,
        scale: 'y2',
        side: 1,
        grid: { show: false },
        ...font,
        size: 80 * k,
        incrs: STEPS,
        values: tickLabels,
      });
    const range = (u, min, max, key) => this.range(u, key, !!plot.unit2);
    const scales = {
      // While zoomed, new data keeps the window; otherwise the axis spans the data.
      x: { time: false, auto: () => this.window === null },
      y: plot.log ? { distr: 3, log: 10, range: logRange } : { range },
    };
    if (plot.unit2) scales.y2 = { range };
    return {
      title: this.title(plot),
      width,
      height: this.height,
      scales,
      series,
      axes,
      cursor: {
        sync: { key: SYNC_KEY, setSeries: false },
        drag: { x: true, y: false },
        bind: {
          dblclick: () => () => {
            this.onFull();
            return null;
          },
        },
      },
      hooks: {
        setScale: [(u, key) => key === 'x' && this.zoomed(u)],
        ready: [(u) => this.pickOnClick(u)],
        draw: [(u) => this.drawMarker(u)],
      },
    };
  }

  /** The y range of `key`: fitted after the start-up transient when framing is on. */
  range(u, key, twoAxes) {
    const { fit, from } = this.framing();
    const start = fit ? from : -Infinity;
    const y = padded(extent(u, 'y', start));
    if (!twoAxes) return y;
    const [a, b] = shareZero(y, padded(extent(u, 'y2', start)));
    return key === 'y2' ? b : a;
  }

  /**
   * Arrow keys on a focused plot move the inspect cursor one sample (Ts), or 1 % of the visible
   * window with Shift; Home and End go to the window's ends.
   */
  keyboard(div, i) {
    div.addEventListener('keydown', (e) => {
      const u = this.charts[i];
      if (!u || !this.full) return;
      const { min, max } = u.scales.x;
      const step = e.shiftKey || !this.sampleTime() ? (max - min) / 100 : this.sampleTime();
      const from = this.marker ?? (min + max) / 2;
      const to = { ArrowRight: from + step, ArrowLeft: from - step, Home: min, End: max }[e.key];
      if (to === undefined) return;
      e.preventDefault();
      const t = Math.min(Math.max(to, this.full[0]), this.full[1]);
      this.mark(t);
      // The legend reads out the samples at the cursor, as it does for the mouse.
      u.setCursor({ left: u.valToPos(t, 'x'), top: u.bbox.height / devicePixelRatio / 2 });
      this.onPick(t);
    });
  }

  /** The text alternative of plot `plot`: its axes, its signals and the run's figures. */
  caption(plot) {
    const units = plot.unit2 ? `${plot.unit} (left) and ${plot.unit2} (right)` : plot.unit;
    const signals = plot.series.map(([, label]) => label).join('; ');
    const keys =
      'Focus the plot and use the arrow keys to inspect the run sample by sample (Shift: 1 % of the window).';
    return `${this.title(plot)}, in ${units} against time t in s. Signals: ${signals}.${this.captions ? ` ${this.captions}` : ''} ${keys}`;
  }

  /** Sets the run's figures (one sentence) that every plot's caption carries. */
  describe(figures) {
    this.captions = figures;
    this.defs.forEach((plot, i) => {
      const caption = this.charts[i]?.root.parentElement.querySelector('.caption');
      if (caption) caption.textContent = this.caption(plot);
    });
  }

  /** Redraws every chart with text and lines `scale` times their normal size (presentation mode). */
  rescale(scale, height) {
    this.scale = scale;
    this.height = height;
    const width = this.width();
    this.charts = this.charts.map((c, i) => {
      const div = c.root.parentElement;
      const data = c.data;
      c.destroy();
      return new uPlot(this.options(this.defs[i], width), data, div);
    });
    if (this.window) for (const c of this.charts) c.setScale('x', { min: this.window[0], max: this.window[1] });
  }

  // A click (not a drag-to-zoom) on the plot area picks the time under the cursor.
  pickOnClick(u) {
    let downX = null;
    u.over.addEventListener('mousedown', (e) => {
      downX = e.clientX;
    });
    u.over.addEventListener('click', (e) => {
      if (downX !== null && Math.abs(e.clientX - downX) < 3 && u.cursor.left >= 0)
        this.onPick(u.posToVal(u.cursor.left, 'x'));
    });
  }

  drawMarker(u) {
    if (this.marker === null) return;
    const x = Math.round(u.valToPos(this.marker, 'x', true));
    if (x < u.bbox.left || x > u.bbox.left + u.bbox.width) return;
    const { ctx } = u;
    ctx.save();
    ctx.strokeStyle = '#b00020';
    ctx.lineWidth = 1.5 * devicePixelRatio;
    ctx.setLineDash([4 * devicePixelRatio, 3 * devicePixelRatio]);
    ctx.beginPath();
    ctx.moveTo(x, u.bbox.top);
    ctx.lineTo(x, u.bbox.top + u.bbox.height);
    ctx.stroke();
    ctx.restore();
  }

  /** Marks the inspected time on every plot (null clears it). */
  mark(t) {
    if (t === this.marker) return;
    this.marker = t;
    for (const c of this.charts) c.redraw(false);
  }

  zoomed(source) {
    if (this.syncing) return;
    const { min, max } = source.scales.x;
    this.window = [min, max];
    this.syncing = true;
    for (const c of this.charts) if (c !== source) c.setScale('x', { min, max });
    this.syncing = false;
    this.onWindow(min, max);
  }

  data(plot, view) {
    const group = view.plots[plot.id];
    const t = group.t;
    const rows = [
      t,
      ...plot.series.map(([col, , , sign = 1, about]) => {
        const values = group.columns[col];
        if (about) return values.map((v, i) => group.columns[about][i] + sign * v);
        return sign === -1 ? values.map((v) => -v) : values;
      }),
    ];
    for (const value of this.constants(plot)) rows.push(new Float64Array(t.length).fill(value));
    return rows;
  }

  /**
   * Creates the charts, empty, so that the first run only fills them: their first layout and the
   * first run of uPlot's code happen while the worker loads the core.
   */
  prepare() {
    if (this.charts.length === 0)
      this.create((plot) => [[], ...plot.series.map(() => []), ...(plot.constants ?? []).map(() => [])]);
  }

  /**
   * Draws each empty chart `rounds` times with made-up data of a run's size (four points a pixel
   * column, as an envelope has), then empties it again in the same task, so that nothing of it is
   * painted: the first run's plots are then drawn by compiled code, not by the interpreter. One
   * chart a task, so that the page stays responsive; stops once a run is shown.
   */
  warm(rounds = 2) {
    const n = 4 * this.width();
    const t = Float64Array.from({ length: n }, (_, i) => i / n);
    const wave = Float64Array.from(t, (x, i) => Math.sin(40 * x) + (i % 4) * 0.1);
    const jobs = this.charts.flatMap((c) => Array.from({ length: rounds }, () => c));
    const next = async () => {
      const c = jobs.shift();
      if (!c || this.full !== null) return;
      if (!this.charts.includes(c)) return next(); // replaced meanwhile (presentation mode)
      const empty = c.data;
      this.syncing = true;
      c.setData([t, ...empty.slice(1).map(() => wave)], true);
      await Promise.resolve(); // uPlot draws in a microtask: this one comes after it
      c.setData(empty, true);
      await Promise.resolve();
      this.syncing = false;
      setTimeout(next, 0);
    };
    setTimeout(next, 0);
  }

  /** Creates a chart for each plot, with the data `data(plot)`. */
  create(data) {
    const width = this.width();
    for (const [i, plot] of this.defs.entries()) {
      // A focusable figure: its caption is the text alternative of the canvas.
      const div = Object.assign(document.createElement('div'), { className: 'plot', tabIndex: 0 });
      div.dataset.plot = plot.id;
      // An embed shows only the plots its link names.
      if (this.embedded?.includes(plot.id)) div.classList.add('embedded');
      div.setAttribute('role', 'figure');
      const caption = Object.assign(document.createElement('p'), {
        className: 'caption sr-only',
        id: `caption-${this.container.id || 'plots'}-${plot.id}`,
      });
      div.setAttribute('aria-describedby', caption.id);
      div.append(caption);
      this.keyboard(div, i);
      (plot.container ?? this.container).append(div);
      this.charts.push(new uPlot(this.options(plot, width), data(plot), div));
      caption.textContent = this.caption(plot);
      div.setAttribute('aria-label', this.title(plot));
    }
  }

  /**
   * Draws a whole run, every chart in this task: an envelope has at most four points per pixel
   * column, so a chart costs the same for any run length.
   */
  show(view, { ifoc = false } = {}) {
    const t = view.plots[this.defs[0].id].t;
    this.full = [t[0], t[t.length - 1]];
    this.window = null;
    this.marker = null;
    this.ifoc = ifoc;
    if (this.charts.length === 0) {
      this.create((plot) => this.data(plot, view));
      return;
    }
    for (const [i, plot] of this.defs.entries()) {
      const title = this.charts[i].root.querySelector('.u-title');
      if (title) title.textContent = this.title(plot);
      this.charts[i].root.parentElement.querySelector('.caption').textContent = this.caption(plot);
      this.charts[i].root.parentElement.setAttribute('aria-label', this.title(plot));
      this.syncing = true;
      this.charts[i].setData(this.data(plot, view), true);
      this.syncing = false;
    }
  }

  /** Replaces the data with that of a zoom window (the axes keep the window) or the whole run. */
  refine(view) {
    if (this.charts.length < this.defs.length) return;
    this.syncing = true;
    this.defs.forEach((plot, i) => this.charts[i].setData(this.data(plot, view), true));
    this.syncing = false;
  }

  /** Forgets the zoom window; the next view shows the whole run. */
  unzoom() {
    this.window = null;
  }

  /** Re-fits the y-axes (after the framing changed). */
  refit() {
    this.syncing = true;
    for (const c of this.charts) c.setData(c.data, true);
    this.syncing = false;
  }

  resize(height = this.height) {
    this.height = height;
    const width = this.width();
    for (const c of this.charts) c.setSize({ width, height });
  }

  /** Each chart's canvas with its title and colour key, for the PNG export. */
  figures() {
    return this.charts.map((c, i) => ({
      canvas: c.ctx.canvas,
      title: this.title(this.defs[i]),
      key: c.series.slice(1).map((s) => ({ label: s.label, stroke: s._stroke ?? s.stroke, dash: s.dash })),
    }));
  }
}
