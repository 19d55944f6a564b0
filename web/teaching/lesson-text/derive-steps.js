// The lesson Derive the four steps yourself. Its texts are messages of
// web/locales/LANG/lessons.ftl, whose numbers are variables of the measurements table
// (web/teaching/measurements/derive-steps.csv, which holds no row: every claim here is a verdict of
// `imlab law`, and every number a setting or a constant of the paper).
export default {
  id: 'derive-steps',
  run: 'v=1&preset=step',
  tab: 'walkthrough',
  plot: 'step1-law', // the residual of the student’s v1
  // Every statement of the answer is a verdict of `imlab law` on this run, each asserted by
  // crate/tests/law.rs: the paper's laws and the x1h/k1 form of v1 give the designed dynamics;
  // k1 for k1s1, the number 1199.95 for k1s1, v2 with the printed (31), a consistent v2 after k1
  // for k1s1, v3 without its factor 2, v4 without the chain-rule terms or si4 are each named.
  holds: [],
  givens: [
    // Names of the walkthrough's steps.
    'under step 1 and write v1',
    'write v2 under step 2, v3 under step 3 and v4 under step 4',
    'as the walkthrough’s step 4 does',
    'step 2 is judged on it, and with your own v3, step 4',
    'named by the verdict of step 3',
    'named by the verdict of step 4',
    'the designed dynamics of step 2',
    // The paper's equations (42)–(47), written as the walkthrough writes them: their coefficients.
    'z4 = 2a10·(x2·x̂4 + x3·x̂5) − v3',
    '2·(x̂4·x̂̇4 + x̂5·x̂̇5)',
    'differentiate 2a10·(x2·x̂4 + x3·x̂5) − v3',
    'ψ3 = −2a8·(x̂4² + x̂5²) − 2a10·(x̃2·x̂4 + x̃3·x̂5) + 2·(x̂4·si4 + x̂5·si5)',
    'dropping the factor 2 throughout',
    'as the walkthrough’s step 2 does',
    'the verdict of step 2',
    // k1s1 = k1 − a3 of the preset: k1 = 1200 1/s and a3 = Cf/J = 0.001/0.02 = 0.05 1/s
    // (`imlab describe 'v=1&preset=step'`: k1, model.cf, model.j; a3 = Cf/J, k1s1 = k1 − a3).
    'its value on this preset, 1199.95',
  ],
};
