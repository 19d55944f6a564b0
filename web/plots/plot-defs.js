// The trajectory plots of the Plots tab: each one's title, units and signals.
import { t } from '../l10n/l10n.js';

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

/**
 * The trajectory plots, their titles and signals in the language shown (its messages are loaded
 * before the page builds its plots).
 * @returns {PlotDef[]}
 */
export const mainPlots = () => [
  {
    id: 'speed',
    title: t('plot-speed'),
    unit: 'rad/s',
    series: [
      ['omega_ref', t('plot-speed-reference')],
      ['omega_hat', t('plot-speed-estimated')],
      ['omega', t('plot-speed-true')],
    ],
  },
  {
    id: 'speed-error',
    title: t('plot-speed-error'),
    unit: 'rad/s',
    series: [['omega_err', 'ω − ω_d']],
  },
  {
    id: 'flux',
    title: t('plot-flux'),
    unit: 'Wb',
    series: [
      ['flux_ref', t('plot-flux-target')],
      ['flux_hat', t('plot-flux-estimated')],
      ['flux', t('plot-flux-true')],
    ],
  },
  {
    id: 'current',
    title: t('plot-current'),
    unit: 'A',
    series: [
      ['i_sa_hat', t('plot-current-a-estimated')],
      ['i_sb_hat', t('plot-current-b-estimated')],
      ['i_sa', t('plot-current-a-true')],
      ['i_sb', t('plot-current-b-true')],
    ],
  },
  {
    id: 'voltage',
    title: t('plot-voltage'),
    unit: 'V',
    constants: [[t('plot-voltage-limit-high')], [t('plot-voltage-limit-low')]],
    series: [
      ['u_a', 'u_sa'],
      ['u_b', 'u_sb'],
    ],
  },
  {
    id: 'z13',
    title: t('plot-z13'),
    unit: 'rad/s',
    unit2: 'Wb²',
    backstepping: true,
    series: [
      ['z1', 'z1 = ω̂ − ω_d (rad/s)'],
      ['z3', t('plot-z13-flux'), 'y2'],
    ],
  },
  {
    id: 'z24',
    title: t('plot-z24'),
    unit: 'rad/s²',
    unit2: 'Wb²/s',
    backstepping: true,
    series: [
      ['z2', t('plot-z24-torque')],
      ['z4', t('plot-z24-flux'), 'y2'],
    ],
  },
  {
    id: 'est',
    title: t('plot-est'),
    unit: 'rad/s',
    unit2: 'Wb',
    series: [
      ['omega_est_err', 'ω − ω̂ (rad/s)'],
      ['flux_est_err', t('plot-est-flux'), 'y2'],
    ],
  },
];
