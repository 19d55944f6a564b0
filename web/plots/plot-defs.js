// The trajectory plots of the Plots tab: each one's title, units and signals.

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
export const NOT_DRIVING = ' (computed for comparison; not driving the motor)';
