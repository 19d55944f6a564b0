// The trajectory plots: uPlot charts with a shared, synchronised time axis.
// Each plot draws the M4 envelope the worker sends for its own columns: every point is a recorded
// sample at its own time, so no zoom draws an edge the samples do not have.
import uPlot from '../../vendor/uPlot.esm.js';
import { t } from '../l10n/l10n.js';
import { chartOptions } from './options.js';
import { inspectByKeys } from './inspect.js';

export { mainPlots } from './plot-defs.js';
export { six } from './numbers.js';

/** @typedef {import('./plot-defs.js').PlotDef} PlotDef */
/** @typedef {import('../worker/protocol.js').View} View */
/** @typedef {[number, number]} Span a time range [t0, t1] */
/**
 * A chart's series as uPlot keeps it: `_stroke`, which its types leave out, is the colour the
 * series was drawn in.
 * @typedef {uPlot.Series & {_stroke?: CanvasRenderingContext2D['strokeStyle']}} DrawnSeries
 */

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
   * @param {HTMLElement} container
   * @param {PlotDef[]} defs the plots' definitions (plot-defs.js)
   * @param {{onWindow: (t0: number, t1: number) => void, onFull: () => void, onPick: (t: number) => void,
   *   constants?: (plot: PlotDef) => number[], framing: () => {fit: boolean, from: number}, height?: number,
   *   sampleTime?: () => number | null, lazy?: boolean}} options
   */
  constructor(
    container,
    defs,
    { onWindow, onFull, onPick, constants = () => [], framing, height = 260, sampleTime = () => null, lazy = false },
  ) {
    this.container = container;
    this.defs = defs;
    this.onWindow = onWindow;
    this.onFull = onFull;
    this.onPick = onPick;
    /** @type {(plot: PlotDef) => number[]} the constant lines of a plot (the voltage limit, the NIS band) */
    this.constants = constants;
    this.framing = framing;
    this.height = height;
    /** @type {() => number | null} */
    this.sampleTime = sampleTime;
    /** @type {string[] | null} the plots shown in an embed */
    this.embedded = null;
    this.scale = 1; // text and line scale: 1, or larger in presentation mode
    this.captions = ''; // the run's figures, as the captions give them
    /** @type {HTMLElement[]} each plot's figure, which holds its chart once drawn */
    this.slots = [];
    /** @type {(uPlot | null)[]} each plot's chart; null while a lazy set has not drawn it */
    this.charts = [];
    /** @type {View | null} the data the charts show (the last view shown or refined), for charts drawn later */
    this.view = null;
    // A lazy set draws a chart when its figure comes within half a screen of the viewport: the
    // first run draws the plots in view, not eight, and a hidden or embedded-out plot costs nothing.
    this.observer = lazy
      ? new IntersectionObserver(
          // It observes the plots' figures only.
          (entries) => entries.forEach((e) => e.isIntersecting && this.draw(/** @type {HTMLElement} */ (e.target))),
          { rootMargin: '50% 0px' },
        )
      : null;
    this.syncing = false;
    /** @type {Span | null} [t0, t1] of the whole run */
    this.full = null;
    /** @type {Span | null} the zoom window, or null for the whole run */
    this.window = null;
    /** @type {number | null} the inspected time */
    this.marker = null;
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

  /** @param {PlotDef} plot */
  title(plot) {
    return plot.backstepping && this.ifoc ? t('plot-not-driving', { title: plot.title }) : plot.title;
  }

  /**
   * The text alternative of plot `plot`: its axes, its signals and the run's figures.
   * @param {PlotDef} plot
   */
  caption(plot) {
    const signals = plot.series.map(([, label]) => label).join('; ');
    const axes = t(plot.unit2 ? 'plot-caption-two-axes' : 'plot-caption', {
      title: this.title(plot),
      unit: plot.unit,
      unit2: plot.unit2 ?? '',
      signals,
    });
    return [axes, this.captions, t('plot-caption-keys')].filter((s) => s !== '').join(' ');
  }

  /**
   * Sets the run's figures (one sentence) that every plot's caption carries.
   * @param {string} figures
   */
  describe(figures) {
    this.captions = figures;
    this.defs.forEach((plot, i) => {
      const caption = this.slots[i]?.querySelector('.caption');
      if (caption) caption.textContent = this.caption(plot);
    });
  }

  /** The charts drawn so far. */
  drawn() {
    return /** @type {uPlot[]} */ (this.charts.filter((c) => c !== null));
  }

  /**
   * Redraws every chart with text and lines `scale` times their normal size (presentation mode).
   * @param {number} scale
   * @param {number} height
   */
  rescale(scale, height) {
    this.scale = scale;
    this.height = height;
    const width = this.width();
    this.charts = this.charts.map((c, i) => {
      if (c === null) return null;
      const data = c.data;
      c.destroy();
      return this.create(i, data, width);
    });
    if (this.observer)
      for (const [i, div] of this.slots.entries()) if (!this.charts[i]) div.style.minHeight = this.held();
  }

  /**
   * Marks the inspected time on every plot (null clears it).
   * @param {number | null} t
   */
  mark(t) {
    if (t === this.marker) return;
    this.marker = t;
    for (const c of this.drawn()) c.redraw(false);
  }

  /**
   * Chart `source` was zoomed by the user: every chart of this set follows its time window, and
   * the window is asked for (the other set follows it then).
   * @param {uPlot} source
   */
  zoomed(source) {
    if (this.syncing) return;
    // A chart's time scale has its range once the chart is drawn.
    const { min, max } = /** @type {{min: number, max: number}} */ (source.scales.x);
    this.follow(min, max);
    this.onWindow(min, max);
  }

  /**
   * Shows the window [t0, t1] on every chart that does not show it yet (the zoomed one does).
   * @param {number} t0
   * @param {number} t1
   */
  follow(t0, t1) {
    this.window = [t0, t1];
    const shown = (/** @type {uPlot} */ c) => c.scales.x.min === t0 && c.scales.x.max === t1;
    this.quietly(() => this.drawn().forEach((c) => shown(c) || c.batch(() => c.setScale('x', { min: t0, max: t1 }))));
  }

  /**
   * Runs \`change\`, which sets the charts' data or scales, as no zoom of the user's: uPlot fires
   * a chart's scale hooks when it commits, which \`batch\` does at once rather than in a microtask.
   * @param {() => void} change
   */
  quietly(change) {
    this.syncing = true;
    try {
      change();
    } finally {
      this.syncing = false;
    }
  }

  /**
   * A new chart of plot \`i\` in its figure, drawn at once with the set's window: its scales are
   * set here, not zoomed by the user.
   * @param {number} i
   * @param {uPlot.AlignedData} data
   * @param {number} width
   */
  create(i, data, width) {
    return new uPlot(chartOptions(this, this.defs[i], width), data, (chart, init) => {
      this.slots[i].appendChild(chart.root);
      const w = this.window;
      this.quietly(() =>
        chart.batch(() => {
          init();
          if (w) chart.setScale('x', { min: w[0], max: w[1] });
        }),
      );
    });
  }

  /**
   * The chart data of `plot` in `view`: its times, its series and its constant lines.
   * @param {PlotDef} plot
   * @param {View} view
   */
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
   * Lays out each plot's figure, empty, while the worker loads the core: a focusable figure whose
   * caption is the text alternative of its canvas. A lazy set's figure holds the chart's height
   * until the chart is drawn.
   */
  prepare() {
    if (this.slots.length) return;
    for (const [i, plot] of this.defs.entries()) {
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
      inspectByKeys(this, div, i);
      (plot.container ?? this.container).append(div);
      caption.textContent = this.caption(plot);
      div.setAttribute('aria-label', this.title(plot));
      this.slots.push(div);
      this.charts.push(null);
      if (this.observer) div.style.minHeight = this.held();
    }
  }

  /** The height a lazy set's figure holds for its chart until it is drawn: the canvas, title and key. */
  held() {
    return `${this.height + 70 * this.scale}px`;
  }

  /**
   * Draws the chart in figure `div`, `width` px wide, with the data shown, unless it is drawn or
   * there is none.
   * @param {HTMLElement} div
   */
  draw(div, width = this.width()) {
    const i = this.slots.indexOf(div);
    if (i < 0 || this.charts[i] !== null || this.view === null) return;
    this.observer?.unobserve(div);
    // The figure gives up its held height first: the chart measures where it lies as it draws.
    div.style.minHeight = '';
    this.charts[i] = this.create(i, this.data(this.defs[i], this.view), width);
  }

  /** Draws every chart not drawn yet (the PNG export takes them all). */
  drawAll() {
    const width = this.width();
    this.slots.forEach((div) => this.draw(div, width));
  }

  /**
   * Whether `div` is in the viewport, and shown.
   * @param {Element} div
   */
  static inView(div) {
    const r = div.getBoundingClientRect();
    return r.height > 0 && r.top < innerHeight && r.bottom > 0;
  }

  /**
   * Draws a whole run, every chart in this task (in a lazy set, the charts in view; the
   * others when they come near it): an envelope has at most four points per pixel column, so a
   * chart costs the same for any run length.
   * @param {View} view
   * @param {{ifoc?: boolean}} [options] whether the IFOC baseline drives the motor
   */
  show(view, { ifoc = false } = {}) {
    const t = view.plots[this.defs[0].id].t;
    this.full = [t[0], t[t.length - 1]];
    this.window = null;
    this.marker = null;
    this.ifoc = ifoc;
    this.view = view;
    this.prepare();
    // The layout is read once, before the charts change it.
    const width = this.width();
    // An embed draws its plots, which are all it shows, at once.
    const now = this.defs.map(
      (plot, i) => !this.observer || !!this.embedded?.includes(plot.id) || Plots.inView(this.slots[i]),
    );
    for (const [i, plot] of this.defs.entries()) {
      const div = this.slots[i];
      // prepare() gave every figure its caption.
      /** @type {Element} */ (div.querySelector('.caption')).textContent = this.caption(plot);
      div.setAttribute('aria-label', this.title(plot));
      const chart = this.charts[i];
      if (chart === null) {
        if (now[i]) this.draw(div, width);
        else this.observer?.observe(div);
        continue;
      }
      const title = chart.root.querySelector('.u-title');
      if (title) title.textContent = this.title(plot);
      this.quietly(() => chart.batch(() => chart.setData(this.data(plot, view), true)));
    }
  }

  /**
   * Replaces the data with that of a zoom window (the axes keep the window) or the whole run.
   * @param {View} view
   */
  refine(view) {
    if (this.view === null) return;
    this.view = view;
    this.quietly(() =>
      this.defs.forEach((plot, i) => {
        const c = this.charts[i];
        c?.batch(() => c.setData(this.data(plot, view), true));
      }),
    );
  }

  /** Forgets the zoom window; the next view shows the whole run. */
  unzoom() {
    this.window = null;
  }

  /** Re-fits the y-axes (after the framing changed). */
  refit() {
    this.quietly(() => this.drawn().forEach((c) => c.batch(() => c.setData(c.data, true))));
  }

  resize(height = this.height) {
    this.height = height;
    const width = this.width();
    for (const c of this.drawn()) c.setSize({ width, height });
  }

  /** Each chart's canvas with its title and colour key, for the PNG export. */
  figures() {
    this.drawAll();
    return this.drawn().map((c) => {
      const i = this.charts.indexOf(c);
      return {
        canvas: c.ctx.canvas,
        title: this.title(this.defs[i]),
        // Every series of a chart has its colour as a string (see seriesOf).
        key: c.series.slice(1).map((s) => ({
          label: s.label,
          stroke: /** @type {DrawnSeries} */ (s)._stroke ?? /** @type {string} */ (s.stroke),
          dash: s.dash,
        })),
      };
    });
  }
}
