// The trajectory plots: uPlot charts with a shared, synchronised time axis.
// They draw what the worker sends (min/max envelopes from the Rust recorder) and nothing else.
import uPlot from '../vendor/uPlot.esm.js';

const COLORS = ['#1f77b4', '#d62728', '#2ca02c', '#9467bd', '#ff7f0e'];
const REFERENCE = '#777';

// [column, label, axis]; axis 'y2' puts a series on the right-hand scale. Later series are drawn
// on top, so the true signals come after their estimates and stay visible.
export const PLOTS = [
  {
    id: 'speed', title: 'Rotor speed', unit: 'rad/s', reference: true,
    series: [['omega_ref', 'ω_d reference'], ['omega_hat', 'ω̂ estimated'], ['omega', 'ω true']],
  },
  {
    id: 'flux', title: 'Rotor-flux modulus', unit: 'Wb', reference: true,
    series: [['flux_ref', '√ψ_d target'], ['flux_hat', '|φ̂| estimated'], ['flux', '|φ| true']],
  },
  {
    id: 'current', title: 'Stator currents', unit: 'A',
    series: [['i_sa_hat', 'î_sa estimated'], ['i_sb_hat', 'î_sb estimated'], ['i_sa', 'i_sa true'], ['i_sb', 'i_sb true']],
  },
  {
    id: 'voltage', title: 'Applied stator voltages (after the limit)', unit: 'V',
    constants: [['+limit'], ['−limit']],
    series: [['u_a', 'u_sa'], ['u_b', 'u_sb']],
  },
  {
    id: 'z13', title: 'Tracking errors', unit: 'rad/s', unit2: 'Wb²',
    series: [['z1', 'z1 = ω̂ − ω_d (rad/s)'], ['z3', 'z3 = |φ̂|² − ψ_d (Wb², right)', 'y2']],
  },
  {
    id: 'z24', title: 'Virtual-control errors', unit: 'rad/s²', unit2: 'Wb²/s',
    series: [['z2', 'z2 torque error (rad/s²)'], ['z4', 'z4 flux-rate error (Wb²/s, right)', 'y2']],
  },
  {
    id: 'est', title: 'Estimation errors', unit: 'rad/s', unit2: 'Wb',
    series: [['omega_est_err', 'ω − ω̂ (rad/s)'], ['flux_est_err', '|φ| − |φ̂| (Wb, right)', 'y2']],
  },
];

const SYNC_KEY = 'imlab-time';

// A log axis spanning whole decades (uPlot's log splits need them), at most 14 below the maximum.
function logRange(u, min, max) {
  const top = Math.ceil(Math.log10(max));
  const bottom = Math.max(Math.floor(Math.log10(min)), top - 14);
  return [10 ** bottom, 10 ** top];
}

// Tick labels that stay readable from 1e-9 to 1e6 (uPlot's default shows tiny values as 0).
function tickLabels(u, splits) {
  return splits.map((v) => (v == null ? '' : String(Number(v.toPrecision(3)))));
}

/** Every column a list of plot definitions needs. */
export function columnsOf(defs) {
  return [...new Set(defs.flatMap((p) => p.series.map((s) => s[0])))];
}

function options(plot, width, height, onZoom, onPick) {
  const series = [{ label: 't (s)', value: (u, v) => (v == null ? '–' : v.toFixed(5)) }];
  plot.series.forEach(([, label, axis], i) => {
    const isRef = i === 0 && plot.reference;
    series.push({
      label,
      scale: axis === 'y2' ? 'y2' : 'y',
      stroke: isRef ? REFERENCE : COLORS[i % COLORS.length],
      dash: isRef ? [6, 4] : undefined,
      width: 2,
      value: (u, v) => (v == null ? '–' : v.toPrecision(6)),
    });
  });
  for (const [label, axis] of plot.constants ?? []) {
    series.push({ label, scale: axis ?? 'y', stroke: '#999', dash: [3, 3], width: 1.5 });
  }
  const font = { font: '14px system-ui', labelFont: '14px system-ui' };
  const axes = [
    { label: 't (s)', ...font },
    { label: plot.unit, scale: 'y', ...font, size: 80, values: tickLabels },
  ];
  if (plot.unit2) axes.push({ label: plot.unit2, scale: 'y2', side: 1, grid: { show: false }, ...font, size: 80, values: tickLabels });
  const scales = { x: { time: false } };
  if (plot.log) scales.y = { distr: 3, log: 10, range: logRange };
  return {
    title: plot.title,
    width,
    height,
    scales,
    series,
    axes,
    cursor: { sync: { key: SYNC_KEY, setSeries: false }, drag: { x: true, y: false } },
    hooks: {
      setScale: [(u, key) => key === 'x' && onZoom(u)],
      ready: [(u) => pickOnClick(u, onPick)],
    },
  };
}

// A click (not a drag-to-zoom) on the plot area picks the time under the cursor.
function pickOnClick(u, onPick) {
  let downX = null;
  u.over.addEventListener('mousedown', (e) => { downX = e.clientX; });
  u.over.addEventListener('click', (e) => {
    if (downX !== null && Math.abs(e.clientX - downX) < 3 && u.cursor.left >= 0) onPick(u.posToVal(u.cursor.left, 'x'));
  });
}

/**
 * A set of plots sharing the synchronised time axis. `onWindow(t0, t1)` is called when the user
 * zooms; `onPick(t)` when the user clicks a time. `constants(plot)` gives the values of a plot's
 * constant lines (limits, bands), which come from the core.
 */
export class Plots {
  constructor(container, defs, { onWindow, onPick, constants = () => [], height = 260 }) {
    Object.assign(this, { container, defs, onWindow, onPick, constants, height });
    this.charts = [];
    this.syncing = false;
    this.full = null; // [t0, t1] of the whole run
  }

  width() {
    return Math.max(320, this.container.clientWidth - 8);
  }

  zoomed(source) {
    if (this.syncing) return;
    const { min, max } = source.scales.x;
    this.syncing = true;
    for (const c of this.charts) if (c !== source) c.setScale('x', { min, max });
    this.syncing = false;
    this.onWindow(min, max);
  }

  data(plot, view) {
    const t = view.columns.t;
    // A series may show a column negated (the lower half of a ±band).
    const rows = [t, ...plot.series.map(([col, , , sign]) => (sign === -1 ? view.columns[col].map((v) => -v) : view.columns[col]))];
    for (const value of this.constants(plot)) rows.push(new Float64Array(t.length).fill(value));
    return rows;
  }

  /** Draws a whole run. */
  show(view) {
    const t = view.columns.t;
    this.full = [t[0], t[t.length - 1]];
    if (this.charts.length === 0) {
      const width = this.width();
      for (const plot of this.defs) {
        const div = document.createElement('div');
        div.className = 'plot';
        div.dataset.plot = plot.id ?? plot.title;
        (plot.container ?? this.container).append(div);
        const opts = options(plot, width, this.height, (u) => this.zoomed(u), (time) => this.onPick(time));
        this.charts.push(new uPlot(opts, this.data(plot, view), div));
      }
    } else {
      this.syncing = true;
      this.defs.forEach((plot, i) => this.charts[i].setData(this.data(plot, view), true));
      this.syncing = false;
    }
  }

  /** Replaces the data inside a zoom window without moving the axes. */
  refine(view) {
    this.syncing = true;
    this.defs.forEach((plot, i) => this.charts[i].setData(this.data(plot, view), false));
    this.syncing = false;
  }

  resize(height = this.height) {
    this.height = height;
    const width = this.width();
    for (const c of this.charts) c.setSize({ width, height });
  }

  /** One PNG of every plot with its title and legend labels. */
  async png() {
    const scale = devicePixelRatio || 1;
    const canvases = this.charts.map((c) => c.ctx.canvas);
    const titleH = 28 * scale;
    const width = Math.max(...canvases.map((c) => c.width));
    const height = canvases.reduce((h, c) => h + c.height + titleH, 0);
    const out = Object.assign(document.createElement('canvas'), { width, height });
    const ctx = out.getContext('2d');
    ctx.fillStyle = '#fff';
    ctx.fillRect(0, 0, width, height);
    let y = 0;
    this.defs.forEach((plot, i) => {
      ctx.fillStyle = '#000';
      ctx.font = `${16 * scale}px system-ui`;
      ctx.fillText(`${plot.title}: ${plot.series.map((s) => s[1]).join(', ')}`, 8 * scale, y + 20 * scale);
      ctx.drawImage(canvases[i], 0, y + titleH);
      y += canvases[i].height + titleH;
    });
    return new Promise((resolve) => out.toBlob(resolve, 'image/png'));
  }
}
