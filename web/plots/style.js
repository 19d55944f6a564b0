// The plots' visual language: a signal has the same colour and dash wherever it is drawn.
// References and bands are dashed grey, true signals blue, estimates orange (b-axis components
// a darker shade of the same colour).
const REFERENCE = { stroke: '#6b6b6b', dash: [6, 4] };
const BAND = { stroke: '#8a8a8a', dash: [3, 3] };

/**
 * How a signal is drawn: its colour, and its dash pattern (solid without one).
 * @typedef {{stroke: string, dash?: number[]}} LineStyle
 */

/** @type {Partial<Record<string, LineStyle>>} each signal's style, by column */
export const STYLE = {
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
  // A step's error rate as the run made it, in its error's colour, against the designed one,
  // dashed grey as a reference is.
  zdot1: { stroke: '#e377c2' },
  zdot2: { stroke: '#17becf' },
  zdot3: { stroke: '#7b4173' },
  zdot4: { stroke: '#e7969c' },
  zdes1: REFERENCE,
  zdes2: REFERENCE,
  zdes3: REFERENCE,
  zdes4: REFERENCE,
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
  d2_tilde: { stroke: '#d62728' },
  d4_tilde: { stroke: '#d62728' },
  load_hat: { stroke: '#ff7f0e' },
  load: { stroke: '#1f77b4' },
  load_band: BAND,
  rr_hat: { stroke: '#ff7f0e' },
  rr: { stroke: '#1f77b4' },
  rr_band: BAND,
};
export const CONSTANT = BAND;
