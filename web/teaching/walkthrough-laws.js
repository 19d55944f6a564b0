// "Write this step": what each backstepping step of the walkthrough says about writing its own
// law, and the plot of its residual (see web/teaching/law-editor.js).

/** @typedef {import('./walkthrough-text.js').SectionPlot} SectionPlot */

/** @type {{step: number, output: string, intro: string, plot: SectionPlot}[]} each step's, in order */
export const LAWS = [
  {
    step: 1,
    output: 'v1',
    intro:
      'Derive v1 yourself and write it below as a formula of this section’s names (x1h for x̂1, wd and dwd for ω_d and ω̇_d, si1, a2, a3, k1s1, z1; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (26) as soon as you press Enter or pause; an empty field gives the paper’s law back. After the run, the verdict checks your law against the designed dynamics ż1 = −k1·z1 + z2 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.',
    plot: {
      title: 'Step 1: your law’s residual, ż1 against the designed ż1 = −k1·z1 + z2 (your v1 less the paper’s)',
      unit: 'rad/s²',
      series: [['law_r1', 'your v1 − the paper’s v1']],
    },
  },
  {
    step: 2,
    output: 'v2',
    intro:
      'Derive v2 yourself and write it below as a formula of this section’s names (v1 and z2 (from step 1), x2 and x3, x4h and x5h, si4 and si5, dxt2 and dxt3, l11 and l12, ddwd, a1 to a10, k1, k1s1, k2s1; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (34) as soon as you press Enter or pause; an empty field gives the paper’s law back. With your own v1 under step 1, your v2 is judged on it: it must differentiate your v1, with the ż1 your v1 gives. After the run, the verdict checks your law against the designed dynamics ż2 = −k2·z2 − z1 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.',
    plot: {
      title:
        'Step 2: your law’s residual, ż2 against the designed ż2 = −k2·z2 − z1 (your v2 less the v2 that gives it: the paper’s, or after your own v1 the one that differentiates yours)',
      unit: 'rad/s³',
      series: [['law_r2', 'your v2 − the v2 that gives ż2']],
    },
  },
  {
    step: 3,
    output: 'v3',
    intro:
      'Derive v3 yourself and write it below as a formula of this section’s names (x4h and x5h, xt2 and xt3, si4 and si5, a8, a10, k3, z3; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (45) as soon as you press Enter or pause; an empty field gives the paper’s law back. After the run, the verdict checks your law against the designed dynamics ż3 = −k3·z3 + z4 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.',
    plot: {
      title: 'Step 3: your law’s residual, ż3 against the designed ż3 = −k3·z3 + z4 (your v3 less the paper’s)',
      unit: 'Wb²/s',
      series: [['law_r3', 'your v3 − the paper’s v3']],
    },
  },
  {
    step: 4,
    output: 'v4',
    intro:
      'Derive v4 yourself and write it below as a formula of this section’s names (v3 and z4 (from step 3), dx4h and dx5h, dxt2 and dxt3, si2 to si5, l41 to l52, a5, a7, a8, a10, k3, k4, z3; the full list is below), with + − * / ^, parentheses and functions. It runs at 20 kHz in place of the paper’s (49) as soon as you press Enter or pause; an empty field gives the paper’s law back. With your own v3 under step 3, your v4 is judged on it: it must differentiate your v3, with the ż3 your v3 gives. After the run, the verdict checks your law against the designed dynamics ż4 = −k4·z4 − z3 at drawn states and parameter values, and the plot below shows its residual over the run: zero for a law that gives them.',
    plot: {
      title:
        'Step 4: your law’s residual, ż4 against the designed ż4 = −k4·z4 − z3 (your v4 less the v4 that gives it: the paper’s, or after your own v3 the one that differentiates yours)',
      unit: 'Wb²/s²',
      series: [['law_r4', 'your v4 − the v4 that gives ż4']],
    },
  },
];
