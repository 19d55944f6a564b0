// The trajectory plots of the Plots tab: each one's title, units and signals.

// Each plot: [column, label, axis, sign, about]; axis 'y2' puts a series on the right-hand scale,
// sign −1 draws the column negated (the lower half of a ±band), and `about` adds the column to
// another (an estimate ± its band). Later series are drawn on top, so the true signals come after
// their estimates and stay visible.

/**
 * A signal of a plot: [column, label, axis, sign, about], as above (an axis of null is the left one).
 * @typedef {[column: string, label: string, axis?: 'y' | 'y2' | null, sign?: number, about?: string]} PlotSeries
 */
/**
 * A plot: its id, its title, the unit of its left axis and, for a plot with a right-hand axis,
 * of that one; its signals; its constant lines, each [label, axis] (their values come from the
 * core); whether its y-axis is logarithmic; whether it shows the backstepping controller's own
 * signals; and the box it goes in, where that is not its set's. A walkthrough plot's constant
 * lines are the NIS band (`nisBand`) or ± the bound its `bound` names (h2 or h4).
 * @typedef {{id: string, title: string, unit: string, unit2?: string, series: PlotSeries[],
 *   constants?: [label: string, axis?: 'y' | 'y2'][], log?: boolean, backstepping?: boolean,
 *   container?: HTMLElement, nisBand?: boolean, bound?: string}} PlotDef
 */

/** @type {PlotDef[]} */
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
export const NOT_DRIVING = ' (computed for comparison; not driving the motor)';
