// "Write this step": what each backstepping step of the walkthrough says about writing its own
// law (the id of its message in web/locales/LANG/walkthrough.ftl), and the plot of its residual
// (see web/teaching/law-editor.js).

/** @typedef {import('./walkthrough-text.js').SectionPlot} SectionPlot */

/** @type {{step: number, output: string, intro: string, plot: SectionPlot}[]} each step's, in order */
export const LAWS = [
  {
    step: 1,
    output: 'v1',
    intro: 'walkthrough-law-1-intro',
    plot: {
      title: 'walkthrough-law-1-plot-title',
      unit: 'rad/s²',
      series: [['law_r1', { id: 'walkthrough-series-law-paper', args: { output: 'v1' } }]],
    },
  },
  {
    step: 2,
    output: 'v2',
    intro: 'walkthrough-law-2-intro',
    plot: {
      title: 'walkthrough-law-2-plot-title',
      unit: 'rad/s³',
      series: [['law_r2', { id: 'walkthrough-series-law-gives', args: { output: 'v2', rate: 'ż2' } }]],
    },
  },
  {
    step: 3,
    output: 'v3',
    intro: 'walkthrough-law-3-intro',
    plot: {
      title: 'walkthrough-law-3-plot-title',
      unit: 'Wb²/s',
      series: [['law_r3', { id: 'walkthrough-series-law-paper', args: { output: 'v3' } }]],
    },
  },
  {
    step: 4,
    output: 'v4',
    intro: 'walkthrough-law-4-intro',
    plot: {
      title: 'walkthrough-law-4-plot-title',
      unit: 'Wb²/s²',
      series: [['law_r4', { id: 'walkthrough-series-law-gives', args: { output: 'v4', rate: 'ż4' } }]],
    },
  },
];
