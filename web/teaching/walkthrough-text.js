// The design walkthrough's text: its sections (prose, display equations with the paper's numbers,
// the plot of each section's live signals and its design knobs) and the stability section's notes.
// The words are messages of web/locales/LANG/walkthrough.ftl, named here by their ids; the
// equations are the TeX below. Every number shown next to them comes from the core. A number of
// the prose about a run is a variable of the message, a row of the measurements table
// (web/teaching/measurements/walkthrough.csv, see web/teaching/measured.js), and what the words
// conclude from it is a condition of WALKTHROUGH_HOLDS: tests/measurements.test.mjs checks both.
const t = String.raw;

import { LAWS } from './walkthrough-laws.js';

/**
 * A label that is a message: its id and its variables (symbols, not words).
 * @typedef {{id: string, args?: Record<string, string>}} Message
 */
/**
 * A label written in symbols alone (`ỹ_a`, `+2σ`), shown as it is, or a message.
 * @typedef {string | Message} Label
 */
/**
 * A plot of a section: its title (a message's id), its units (left and right axes), its series
 * as the trajectory plots' (web/plots/plot-defs.js: column, label, 'y2' for the right axis, sign,
 * the column it is about), a log scale, and its constant lines: the NIS band, or ± the
 * scenario's field `bound`.
 * @typedef {{title: string, unit: Label, unit2?: string, log?: boolean, nisBand?: boolean, bound?: string,
 *   series: [column: string, label: Label, axis?: 'y2' | null, sign?: number, about?: string][]}} SectionPlot
 */
/**
 * A section: the ids of its title, prose paragraphs and notes, its equations, a figure (its
 * caption's message, whose `alt` is the image's text), the boxes its results fill (`lumped`,
 * `stability`, `compare`), its plots, the step whose law a student may write, and its knobs.
 * @typedef {{id: string, title: string, prose: string[], equations: string[], note?: string, shows?: string[],
 *   figure?: {src: string, text: string}, lumped?: boolean, stability?: boolean, compare?: boolean,
 *   plot?: SectionPlot, plot2?: SectionPlot, plot3?: SectionPlot, plot4?: SectionPlot, plot5?: SectionPlot,
 *   plot6?: SectionPlot, law?: {step: number, output: string, intro: string, plot: SectionPlot},
 *   knobs: string[]}} Section
 */

/**
 * A label that is the message `id` with `args`.
 * @param {string} id
 * @param {Record<string, string>} [args]
 * @returns {Message}
 */
export const m = (id, args) => (args ? { id, args } : { id });

// Each section: prose paragraphs, display equations (TeX), the plot of its live signals
// ([column, label, 'y2' for the right axis]) and the scenario fields that are its design knobs.
/** @type {Section[]} */
export const SECTIONS = [
  {
    id: 'model',
    title: 'walkthrough-model-title',
    prose: ['walkthrough-model-prose-1', 'walkthrough-model-prose-2'],
    equations: [
      t`\dot x_1 = a_1(x_3x_4 - x_2x_5) - a_2 - a_3x_1\qquad (2)`,
      t`\dot x_2 = a_5x_4 + a_6x_1x_5 - a_7x_2 + b\,u_1,\quad \dot x_3 = a_5x_5 - a_6x_1x_4 - a_7x_3 + b\,u_2`,
      t`\dot x_4 = -a_8x_4 - a_9x_1x_5 + a_{10}x_2,\quad \dot x_5 = -a_8x_5 + a_9x_1x_4 + a_{10}x_3`,
      t`\sigma = L_s - \tfrac{M^2}{L_r},\ \alpha = \tfrac{R_r}{L_r},\ \beta = \tfrac{M}{\sigma L_r},\ a_1 = \tfrac{3n_pM}{2JL_r},\ a_5 = \alpha\beta,\ a_6 = n_p\beta,\ a_7 = \tfrac{R_s}{\sigma} + \alpha\beta M,\ a_8 = \alpha,\ a_9 = n_p,\ a_{10} = \alpha M,\ b = \tfrac1\sigma`,
    ],
    note: 'walkthrough-model-note',
    lumped: true,
    plot: {
      title: 'walkthrough-model-plot-title',
      unit: 'rad/s',
      unit2: 'Wb',
      series: [
        ['omega', 'ω (rad/s)'],
        ['flux', m('walkthrough-series-right-unit', { signal: '|φ|', unit: 'Wb' }), 'y2'],
      ],
    },
    knobs: ['plant.rr', 'model.rr', 'load.torque'],
  },
  {
    id: 'ekf',
    title: 'walkthrough-ekf-title',
    prose: ['walkthrough-ekf-prose-1', 'walkthrough-ekf-prose-2', 'walkthrough-ekf-prose-3', 'walkthrough-ekf-prose-4'],
    equations: [
      t`\hat x_{k|k-1} = \hat x_{k-1|k-1} + T_s f(\hat x_{k-1|k-1}, u_{k-1})\quad (10),(13),\qquad A_{k-1} = I + T_s \tfrac{\partial f}{\partial x}\Big|_{\hat x_{k-1|k-1}}\quad (11),(12)`,
      t`P_{k|k-1} = A_{k-1}P_{k-1|k-1}A_{k-1}^T + Q\ (14),\qquad \tilde y_k = y_k - C\hat x_{k|k-1}\ (15),\qquad S_k = CP_{k|k-1}C^T + R\ (16)`,
      t`K_k = P_{k|k-1}C^TS_k^{-1}\ (17),\qquad \hat x_{k|k} = \hat x_{k|k-1} + K_k\tilde y_k\ (18),\qquad L = K_k/T_s\ (20)`,
      t`P_{k|k} = (I - K_kC)P_{k|k-1}(I - K_kC)^T + K_kRK_k^T\quad\text{(Joseph form of (19))}`,
    ],
    note: 'walkthrough-ekf-note',
    plot: {
      title: 'walkthrough-ekf-plot-title',
      unit: 'A',
      series: [
        ['innov_a', 'ỹ_a'],
        ['innov_band_a', '+2σ'],
        ['innov_band_a', '−2σ', null, -1],
      ],
    },
    plot4: {
      title: 'walkthrough-ekf-plot4-title',
      unit: 'NIS',
      series: [['nis', 'NIS']],
      nisBand: true,
    },
    plot2: {
      title: 'walkthrough-ekf-plot2-title',
      unit: 'rad/s',
      unit2: '(rad/s)²',
      series: [
        ['omega_hat', m('walkthrough-series-estimated', { signal: 'ω̂' })],
        ['omega', m('walkthrough-series-true', { signal: 'ω' })],
        ['p_omega', m('walkthrough-series-right', { signal: 'P₁₁' }), 'y2'],
      ],
    },
    plot3: {
      title: 'walkthrough-ekf-plot3-title',
      unit: 'Wb',
      series: [
        ['flux_hat', m('walkthrough-series-estimated', { signal: '|φ̂|' })],
        ['flux', m('walkthrough-series-true', { signal: '|φ|' })],
      ],
    },
    // The remedies of Section 3.1: with ekf.load=1 or ekf.rr=1 the estimate moves, with its ±2σ
    // band from P; otherwise it is the model's fixed value against the truth.
    plot5: {
      title: 'walkthrough-ekf-plot5-title',
      unit: 'N m',
      series: [
        ['load_band', 'T̂_L + 2σ', null, 1, 'load_hat'],
        ['load_band', 'T̂_L − 2σ', null, -1, 'load_hat'],
        ['load_hat', m('walkthrough-series-estimated', { signal: 'T̂_L' })],
        ['load', m('walkthrough-series-load-true')],
      ],
    },
    plot6: {
      title: 'walkthrough-ekf-plot6-title',
      unit: 'Ω',
      series: [
        ['rr_band', 'R̂_r + 2σ', null, 1, 'rr_hat'],
        ['rr_band', 'R̂_r − 2σ', null, -1, 'rr_hat'],
        ['rr_hat', m('walkthrough-series-estimated', { signal: 'R̂_r' })],
        ['rr', m('walkthrough-series-rr-motor')],
      ],
    },
    knobs: ['ekf', 'ekf.q', 'ekf.q_speed', 'ekf.r_std', 'ekf.load', 'ekf.q_load', 'ekf.rr', 'ekf.q_rr'],
    compare: true,
  },
  {
    id: 'bridge',
    title: 'walkthrough-bridge-title',
    prose: [
      'walkthrough-bridge-prose-1',
      'walkthrough-bridge-prose-2',
      'walkthrough-bridge-prose-3',
      'walkthrough-bridge-prose-4',
      'walkthrough-bridge-prose-5',
    ],
    equations: [
      t`\dot{\hat x}_1 = a_1(x_3\hat x_4 - x_2\hat x_5) - \hat a_2 - a_3\hat x_1 + s_{i1},\qquad \dot{\hat x}_2 = a_5\hat x_4 + a_6\hat x_1\hat x_5 - a_7\hat x_2 + bu_1 + s_{i2}\qquad (4)`,
      t`\dot{\hat x}_3 = a_5\hat x_5 - a_6\hat x_1\hat x_4 - a_7\hat x_3 + bu_2 + s_{i3},\quad \dot{\hat x}_4 = -a_8\hat x_4 - a_9\hat x_1\hat x_5 + a_{10}\hat x_2 + s_{i4},\quad \dot{\hat x}_5 = -a_8\hat x_5 + a_9\hat x_1\hat x_4 + a_{10}\hat x_3 + s_{i5}`,
      t`\tilde x = x - \hat x,\qquad s_{ik} = l_{k1}\tilde x_2 + l_{k2}\tilde x_3,\ k = 1,\dots,5\quad (5),\qquad L = [l_{kj}] = K_k/T_s`,
      t`\dot{\tilde x}_2 = \underbrace{-(a_7 + l_{21})\tilde x_2 - l_{22}\tilde x_3}_{\text{nominal}} + a_5\tilde x_4 + a_6(\hat x_1\tilde x_5 + x_5\tilde x_1)`,
      t`\dot{\tilde x}_3 = \underbrace{-l_{31}\tilde x_2 - (a_7 + l_{32})\tilde x_3}_{\text{nominal}} + a_5\tilde x_5 - a_6(\hat x_1\tilde x_4 + x_4\tilde x_1)`,
    ],
    figure: {
      src: 'structure.svg',
      text: 'walkthrough-bridge-figure',
    },
    note: 'walkthrough-bridge-note',
    knobs: [],
  },
  {
    id: 'step1',
    title: 'walkthrough-step1-title',
    prose: [
      'walkthrough-step1-prose-1',
      'walkthrough-step1-prose-2',
      'walkthrough-step1-prose-3',
      'walkthrough-step1-prose-4',
      'walkthrough-step1-prose-5',
    ],
    equations: [
      t`z_1 = \hat x_1 - \omega_d,\qquad \dot z_1 = -a_3z_1 + a_1(x_3\hat x_4 - x_2\hat x_5) + s_{i1} - \dot\omega_d - a_3\omega_d - \hat a_2\qquad (23)`,
      t`z_2 = a_1(x_3\hat x_4 - x_2\hat x_5) - v_1\quad (24),\qquad \dot z_1 = -a_3z_1 + v_1 + z_2 + s_{i1} - \dot\omega_d - a_3\omega_d - \hat a_2\quad (25)`,
      t`v_1 = v_{1a} + v_{1s}\ (26),\quad v_{1a} = -s_{i1} + \dot\omega_d + a_3\omega_d + \hat a_2\ (27),\quad v_{1s} = -k_{1s1}z_1\ (28)`,
      t`\dot z_1 = -k_1z_1 + z_2,\quad k_1 = a_3 + k_{1s1}\quad (29),\qquad V_1 = \tfrac12z_1^2,\quad \dot V_1 = -k_1z_1^2 + z_1z_2`,
      t`v_1 = -k_{1s1}z_1 - s_{i1} + \dot\omega_d + a_3\omega_d + \hat a_2\quad (30)`,
      t`\dot v_1 = k_{1s1}k_1z_1 - k_{1s1}z_2 + (l_{11}a_7 + l_{11}l_{21} + l_{12}l_{31})\tilde x_2 + (l_{12}a_7 + l_{11}l_{22} + l_{12}l_{32})\tilde x_3 + \ddot\omega_d + a_3\dot\omega_d + \dot{\hat a}_2 + \ldots\quad (31)`,
    ],
    note: 'walkthrough-step1-note',
    plot: {
      title: 'walkthrough-step1-plot-title',
      unit: 'rad/s²',
      unit2: 'rad/s',
      series: [
        ['v1', 'v1'],
        ['v1a', m('walkthrough-series-feedforward', { term: 'v1a' })],
        ['v1s', m('walkthrough-series-feedback', { term: 'v1s' })],
        ['torque_hat', 'a1(x3x̂4 − x2x̂5)'],
        ['z1', m('walkthrough-series-right-unit', { signal: 'z1', unit: 'rad/s' }), 'y2'],
      ],
    },
    plot3: {
      title: 'walkthrough-step1-plot3-title',
      unit: 'rad/s²',
      series: [
        ['zdot1', m('walkthrough-series-run', { signal: 'ż1' })],
        ['zdes1', m('walkthrough-series-designed', { expression: '−k1·z1 + z2' })],
      ],
    },
    law: LAWS[0],
    knobs: ['k1'],
  },
  {
    id: 'step2',
    title: 'walkthrough-step2-title',
    prose: [
      'walkthrough-step2-prose-1',
      'walkthrough-step2-prose-2',
      'walkthrough-step2-prose-3',
      'walkthrough-step2-prose-4',
      'walkthrough-step2-prose-5',
      'walkthrough-step2-prose-6',
    ],
    shows: ['walkthrough-step2-shows-1'],
    equations: [
      t`\dot z_2 = a_1(\dot x_3\hat x_4 - \dot x_2\hat x_5) + a_1(x_3\dot{\hat x}_4 - x_2\dot{\hat x}_5) - \dot v_1`,
      t`\dot z_2 = v_2 + \psi_2 - (a_7 + a_8)z_2 + \tilde d_2\quad (32),\qquad v_2 = b\,a_1(\hat x_4u_2 - \hat x_5u_1)`,
      t`\psi_2 = -(a_7 + a_8)v_1 - a_1a_6\hat x_1(\hat x_4^2 + \hat x_5^2) - a_1a_9\hat x_1(\hat x_5x_3 + \hat x_4x_2) + a_1a_{10}(\hat x_2x_3 - \hat x_3x_2) + a_1(x_3s_{i4} - x_2s_{i5}) - \dot v_1^{\,\text{known}}\quad (33)`,
      t`\tilde d_2 = a_1a_5(\tilde x_5\hat x_4 - \tilde x_4\hat x_5) - a_1a_6x_1(\tilde x_4\hat x_4 + \tilde x_5\hat x_5) - a_1a_6\tilde x_1(\hat x_4^2 + \hat x_5^2)`,
      t`\quad + (l_{11}a_5 - l_{12}a_6\hat x_1)\tilde x_4 + (l_{12}a_5 + l_{11}a_6\hat x_1)\tilde x_5 + (l_{11}a_6x_5 - l_{12}a_6x_4)\tilde x_1\quad (33)`,
      t`v_2 = v_{2a} + v_{2s}\ (34),\quad v_{2a} = -\psi_2 - z_1\ (35),\quad v_{2s} = -k_{2s1}z_2 + v_{2s2},\quad k_2 = a_7 + a_8 + k_{2s1}\ (36)`,
      t`\dot z_2 = -k_2z_2 - z_1 + v_{2s2} + \tilde d_2\quad (37),\qquad v_{2s2} = -\tfrac{h_2^2}{4\epsilon_2}z_2\quad (38)`,
      t`V_{s2} = \tfrac12z_1^2 + \tfrac12z_2^2\quad (39),\qquad \dot V_{s2} = -k_1z_1^2 - k_2z_2^2 + z_2(v_{2s2} + \tilde d_2) \le -k_1z_1^2 - k_2z_2^2 + \epsilon_2\quad (40)`,
    ],
    note: 'walkthrough-step2-note',
    plot: {
      title: 'walkthrough-step2-plot-title',
      unit: 'rad/s³',
      unit2: 'rad/s²',
      series: [
        ['v2', 'v2'],
        ['v2a', m('walkthrough-series-feedforward', { term: 'v2a' })],
        ['v2s', m('walkthrough-series-feedback', { term: 'v2s' })],
        ['z2', m('walkthrough-series-right-unit', { signal: 'z2', unit: 'rad/s²' }), 'y2'],
      ],
    },
    plot2: {
      title: 'walkthrough-step2-plot2-title',
      unit: 'rad/s³',
      series: [['d2_tilde', 'd̃2']],
      bound: 'h2',
    },
    plot3: {
      title: 'walkthrough-step2-plot3-title',
      unit: 'rad/s³',
      series: [
        ['zdot2', m('walkthrough-series-run', { signal: 'ż2' })],
        ['zdes2', m('walkthrough-series-designed', { expression: '−k2·z2 − z1' })],
      ],
    },
    law: LAWS[1],
    knobs: ['k2', 'robust', 'eps2', 'h2'],
  },
  {
    id: 'step3',
    title: 'walkthrough-step3-title',
    prose: [
      'walkthrough-step3-prose-1',
      'walkthrough-step3-prose-2',
      'walkthrough-step3-prose-3',
      'walkthrough-step3-prose-4',
    ],
    shows: ['walkthrough-step3-shows-1'],
    equations: [
      t`z_3 = \hat x_4^2 + \hat x_5^2 - \psi_d\quad (42),\qquad \dot z_3 = 2\hat x_4\dot{\hat x}_4 + 2\hat x_5\dot{\hat x}_5 - \dot\psi_d = -2a_8(\hat x_4^2 + \hat x_5^2) + 2a_{10}(\hat x_2\hat x_4 + \hat x_3\hat x_5) + 2\hat x_4s_{i4} + 2\hat x_5s_{i5} - \dot\psi_d`,
      t`\dot z_3 = 2a_{10}(x_2\hat x_4 + x_3\hat x_5) + \psi_3\quad (43)`,
      t`\psi_3 = -2a_8(\hat x_4^2 + \hat x_5^2) - 2a_{10}(\tilde x_2\hat x_4 + \tilde x_3\hat x_5) + 2\hat x_4s_{i4} + 2\hat x_5s_{i5} - \dot\psi_d`,
      t`z_4 = 2a_{10}(x_2\hat x_4 + x_3\hat x_5) - v_3\quad (44),\qquad v_3 = v_{3a} + v_{3s},\quad v_{3a} = -\psi_3,\quad v_{3s} = -k_3z_3\quad (45)`,
      t`\dot z_3 = -k_3z_3 + z_4\quad (46),\qquad z_4 = \dot z_3 + k_3z_3,\qquad V_3 = \tfrac12z_3^2,\quad \dot V_3 = -k_3z_3^2 + z_3z_4`,
    ],
    note: 'walkthrough-step3-note',
    plot: {
      title: 'walkthrough-step3-plot-title',
      unit: 'Wb²/s',
      unit2: 'Wb²',
      series: [
        ['v3', 'v3'],
        ['v3a', m('walkthrough-series-feedforward', { term: 'v3a' })],
        ['v3s', m('walkthrough-series-feedback', { term: 'v3s' })],
        ['z3', m('walkthrough-series-right-unit', { signal: 'z3', unit: 'Wb²' }), 'y2'],
      ],
    },
    plot3: {
      title: 'walkthrough-step3-plot3-title',
      unit: 'Wb²/s',
      series: [
        ['zdot3', m('walkthrough-series-run', { signal: 'ż3' })],
        ['zdes3', m('walkthrough-series-designed', { expression: '−k3·z3 + z4' })],
      ],
    },
    law: LAWS[2],
    knobs: ['k3', 'psi_d'],
  },
  {
    id: 'step4',
    title: 'walkthrough-step4-title',
    prose: [
      'walkthrough-step4-prose-1',
      'walkthrough-step4-prose-2',
      'walkthrough-step4-prose-3',
      'walkthrough-step4-prose-4',
    ],
    shows: ['walkthrough-step4-shows-1', 'walkthrough-step4-shows-2'],
    equations: [
      t`\dot z_4 = v_4 + \psi_4 + \tilde d_4\quad (47),\qquad v_4 = a_{41}bu_1 + a_{42}bu_2,\quad a_{41} = 2a_{10}\hat x_4,\ a_{42} = 2a_{10}\hat x_5\quad (48)`,
      t`\psi_4 = 2a_{10}a_5(\hat x_4^2 + \hat x_5^2) - 2a_{10}a_7(\hat x_2\hat x_4 + \hat x_3\hat x_5) + 2a_{10}(\hat x_4s_{i2} + \hat x_5s_{i3})`,
      t`\quad + 2(l_{41}\hat x_4 + l_{51}\hat x_5)\dot{\tilde x}_2^{\,\text{nom}} + 2(l_{42}\hat x_4 + l_{52}\hat x_5)\dot{\tilde x}_3^{\,\text{nom}} + 2(s_{i4} + a_{10}\hat x_2 - 2a_8\hat x_4)\dot{\hat x}_4 + 2(s_{i5} + a_{10}\hat x_3 - 2a_8\hat x_5)\dot{\hat x}_5 + k_3(-k_3z_3 + z_4) - \ddot\psi_d`,
      t`\tilde d_4 = 2(l_{41}\hat x_4 + l_{51}\hat x_5)\big(a_5\tilde x_4 + a_6(\hat x_1\tilde x_5 + x_5\tilde x_1)\big) + 2(l_{42}\hat x_4 + l_{52}\hat x_5)\big(a_5\tilde x_5 - a_6(\hat x_1\tilde x_4 + x_4\tilde x_1)\big)`,
      t`v_4 = v_{4a} + v_{4s}\ (49),\quad v_{4a} = -\psi_4 - z_3\ (50),\quad v_{4s} = -k_4z_4 + v_{4s2}\ (51),\quad v_{4s2} = -\tfrac{h_4^2}{4\epsilon_4}z_4\ (53)`,
      t`\dot z_4 = -k_4z_4 - z_3 + v_{4s2} + \tilde d_4\quad (52),\qquad V_{s4} = \tfrac12z_3^2 + \tfrac12z_4^2\quad (56)`,
      t`\begin{bmatrix}u_1\\u_2\end{bmatrix} = \frac1b\begin{bmatrix}-a_1\hat x_5 & a_1\hat x_4\\ 2a_{10}\hat x_4 & 2a_{10}\hat x_5\end{bmatrix}^{-1}\begin{bmatrix}v_2\\v_4\end{bmatrix}\quad (54),\qquad \det = -2a_1a_{10}(\hat x_4^2 + \hat x_5^2) \ne 0\quad (55)`,
    ],
    note: 'walkthrough-step4-note',
    plot: {
      title: 'walkthrough-step4-plot-title',
      unit: 'V',
      unit2: 'Wb²/s',
      series: [
        ['u_a_cmd', m('walkthrough-series-u-commanded')],
        ['u_a', m('walkthrough-series-u-applied')],
        ['z4', m('walkthrough-series-right-unit', { signal: 'z4', unit: 'Wb²/s' }), 'y2'],
      ],
    },
    plot2: {
      title: 'walkthrough-step4-plot2-title',
      unit: 'Wb²/s²',
      series: [['d4_tilde', 'd̃4']],
      bound: 'h4',
    },
    plot3: {
      title: 'walkthrough-step4-plot3-title',
      unit: 'Wb²/s²',
      series: [
        ['zdot4', m('walkthrough-series-run', { signal: 'ż4' })],
        ['zdes4', m('walkthrough-series-designed', { expression: '−k4·z4 − z3' })],
      ],
    },
    law: LAWS[3],
    knobs: ['k4', 'robust', 'eps4', 'h4', 'vmax'],
  },
  {
    id: 'stability',
    title: 'walkthrough-stability-title',
    prose: [
      'walkthrough-stability-prose-1',
      'walkthrough-stability-prose-2',
      'walkthrough-stability-prose-3',
      'walkthrough-stability-prose-4',
    ],
    shows: ['walkthrough-stability-shows-1'],
    equations: [
      t`z_2(v_{2s2} + \tilde d_2) \le h_2|z_2| - \tfrac{h_2^2}{4\epsilon_2}z_2^2 = \epsilon_2 - \Big(\tfrac{h_2|z_2|}{2\sqrt{\epsilon_2}} - \sqrt{\epsilon_2}\Big)^2 \le \epsilon_2`,
      t`V_s = \tfrac12(z_1^2 + z_2^2 + z_3^2 + z_4^2)\quad (58),\qquad \dot V_s \le -\lambda V_s + \epsilon,\qquad \lambda = 2\min(k_1,k_2,k_3,k_4),\ \epsilon = \epsilon_2 + \epsilon_4\quad (60)`,
      t`\tfrac{d}{dt}\big(e^{\lambda t}V_s\big) = e^{\lambda t}(\dot V_s + \lambda V_s) \le \epsilon e^{\lambda t}\ \Rightarrow\ V_s(t) \le e^{-\lambda t}V_s(0) + \frac{\epsilon}{\lambda}\left(1 - e^{-\lambda t}\right)\qquad (59)`,
    ],
    plot: {
      title: 'walkthrough-stability-plot-title',
      unit: m('walkthrough-stability-plot-unit'),
      log: true,
      series: [
        ['lyapunov', m('walkthrough-series-lyapunov')],
        ['lyapunov_bound', m('walkthrough-series-bound')],
      ],
    },
    knobs: ['robust', 'eps2', 'h2', 'eps4', 'h4'],
    stability: true,
  },
];

// What the stability section adds when V leaves the bound (59), by the core's most likely cause:
// the id of its message.
/** @type {Partial<Record<string, string>>} */
export const STABILITY_CAUSES = {
  saturation: 'walkthrough-stability-cause-saturation',
  sampling: 'walkthrough-stability-cause-sampling',
  estimation_errors: 'walkthrough-stability-cause-estimation-errors',
  eps_or_sampling: 'walkthrough-stability-cause-eps-or-sampling',
};

// What the words conclude from the measurements, and the settings and constants they name.
export { WALKTHROUGH_GIVENS, WALKTHROUGH_HOLDS } from './walkthrough-measured.js';
