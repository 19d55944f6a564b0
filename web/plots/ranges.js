// The y-axes' ranges: fitted to the signals shown (after the start-up transient when asked),
// padded, on whole decades for a log axis, and with zero level on both axes of a two-axis plot.

/** @typedef {[number, number]} Span a range [lo, hi] */

/**
 * A log axis spanning whole decades (uPlot's log splits need them), at most 14 below the maximum.
 * @param {uPlot} u
 * @param {number} min
 * @param {number} max
 * @returns {Span}
 */
export function logRange(u, min, max) {
  const top = Math.ceil(Math.log10(max));
  const bottom = Math.max(Math.floor(Math.log10(min)), top - 14);
  return [10 ** bottom, 10 ** top];
}

/**
 * Min and max of the series on `scale` over the samples with t ≥ from (all of them if none).
 * @param {uPlot} u
 * @param {string} scale
 * @param {number} from
 * @returns {Span}
 */
function extent(u, scale, from) {
  const t = u.data[0];
  /** @type {(start: number) => Span} */
  const scan = (start) => {
    let lo = Infinity;
    let hi = -Infinity;
    for (let s = 1; s < u.series.length; s++) {
      if (u.series[s].scale !== scale || !u.series[s].show) continue;
      const y = u.data[s];
      for (let j = 0; j < t.length; j++) {
        if (t[j] < start) continue;
        // The charts fitted here hold numbers only, never null (which would compare as 0).
        const v = /** @type {number} */ (y[j]);
        if (v < lo) lo = v;
        if (v > hi) hi = v;
      }
    }
    return [lo, hi];
  };
  const fitted = scan(from);
  return fitted[0] <= fitted[1] ? fitted : scan(-Infinity);
}

/**
 * [lo, hi] padded by 5 % (a flat signal gets a band of its own size, or ±1 at zero).
 * @param {Span} span
 * @returns {Span}
 */
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
 * @param {Span} a
 * @param {Span} b
 * @returns {[Span, Span]}
 */
function shareZero(a, b) {
  /** @type {(span: Span) => number} */
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
  /** @type {[Span, Span]} */
  const aligned =
    lowered <= raised
      ? [[Math.min(low[0], (-f1 * low[1]) / (1 - f1)), low[1]], high]
      : [low, [high[0], Math.max(high[1], (-high[0] * (1 - f0)) / f0)]];
  return fa < fb ? aligned : [aligned[1], aligned[0]];
}

/**
 * The y range of `key`: fitted after the start-up transient when `framing` says so.
 * @param {uPlot} u
 * @param {string} key
 * @param {boolean} twoAxes
 * @param {{fit: boolean, from: number}} framing
 * @returns {Span}
 */
export function fittedRange(u, key, twoAxes, { fit, from }) {
  const start = fit ? from : -Infinity;
  const y = padded(extent(u, 'y', start));
  if (!twoAxes) return y;
  const [a, b] = shareZero(y, padded(extent(u, 'y2', start)));
  return key === 'y2' ? b : a;
}
