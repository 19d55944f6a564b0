// The trajectory plots: uPlot charts with a shared, synchronised time axis.
// Each plot draws the M4 envelope the worker sends for its own columns: every point is a recorded
// sample at its own time, so no zoom draws an edge the samples do not have.
import uPlot from '../../vendor/uPlot.esm.js';
import { NOT_DRIVING } from './plot-defs.js';
import { chartOptions } from './options.js';
import { inspectByKeys } from './inspect.js';

export { PLOTS } from './plot-defs.js';
export { six } from './numbers.js';

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
   * @param {any[]} defs the plots' definitions (plot-defs.js)
   * @param {{onWindow: (t0: number, t1: number) => void, onFull: () => void, onPick: (t: number) => void,
   *   constants?: (plot: any) => number[], framing: () => {fit: boolean, from: number}, height?: number,
   *   sampleTime?: () => number | null}} options
   */
  constructor(
    container,
    defs,
    { onWindow, onFull, onPick, constants = () => [], framing, height = 260, sampleTime = () => null },
  ) {
    this.container = container;
    this.defs = defs;
    this.onWindow = onWindow;
    this.onFull = onFull;
    this.onPick = onPick;
    /** @type {(plot: any) => number[]} the constant lines of a plot (the voltage limit, the NIS band) */
    this.constants = constants;
    this.framing = framing;
    this.height = height;
    /** @type {() => number | null} */
    this.sampleTime = sampleTime;
    /** @type {string[] | null} the plots shown in an embed */
    this.embedded = null;
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
      return new uPlot(chartOptions(this, this.defs[i], width), data, div);
    });
    if (this.window) for (const c of this.charts) c.setScale('x', { min: this.window[0], max: this.window[1] });
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
      inspectByKeys(this, div, i);
      (plot.container ?? this.container).append(div);
      this.charts.push(new uPlot(chartOptions(this, plot, width), data(plot), div));
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
