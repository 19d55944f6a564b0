// The lesson Derive the four steps yourself. Numbers are placeholders of the measurements table
// (web/teaching/measurements/derive-steps.csv, which holds no row: every claim here is a verdict
// of `imlab law`, and every number a setting or a constant of the paper); see web/teaching/measured.js.
export default {
  id: 'derive-steps',
  run: 'v=1&preset=step',
  title: 'Derive the four steps yourself',
  tab: 'walkthrough',
  look: 'In the design walkthrough, open “Write this step” under step 1 and write v1 in the names listed there; press Enter to run it. The verdict under your law says whether it gives the designed dynamics ż1 = −k1·z1 + z2, and the plot below it shows the residual, your v1 less the paper’s, over the run. Then write v2 under step 2 (with the paper’s v1 or yours), v3 under step 3 and v4 under step 4.',
  question:
    'Which v1 makes ż1 = −k1·z1 + z2, when ż1 = a1·(x3·x̂4 − x2·x̂5) − a3·x̂1 − a2 + si1 − ω̇_d and z2 = a1·(x3·x̂4 − x2·x̂5) − v1? Which v2 then gives ż2 = −k2·z2 − z1?',
  hint: 'Put z2 into ż1 and solve for v1: every term of ż1 but the torque is cancelled, and −k1·z1 is added. The paper writes a3·x̂1 as a3·z1 + a3·ω_d, so its gain on z1 is k1s1 = k1 − a3 (27)–(28). For v2, differentiate z2 along the observer (4), as the walkthrough’s step 2 does, and compare your terms with ψ2 of (33).',
  answer:
    'v1 = −si1 + ω̇_d + a3·ω_d + a2 − k1s1·z1, which is (26)–(28). Written as dwd - si1 + a2 + a3*x1h - k1*z1 it is the same law, and the verdict says it gives the designed dynamics. With k1 in place of k1s1 a3·z1 is left over, tiny beside k1·z1 on this preset, and the verdict still names it. So does k1s1 written as its value on this preset, 1199.95: the verdict draws the parameter values and gains as well as the states, and a law must hold for all of them. v2 = −ψ2 − z1 − k2s1·z2 with k2s1 = k2 − a7 − a8, ψ2 of (33) and v̇1 of (31) with its typos corrected; copying the printed (31), with a3·ω_d for a3·ω̇_d, is named by the verdict of step 2.',
  // Every statement of the answer is a verdict of `imlab law` on this run, checked by hand:
  // the paper's v1 and the x1h/k1 form give the designed dynamics; k1 for k1s1 ("it has k1
  // where (28) has k1s1"), the number 1199.95 for k1s1 ("written as its number") and v2 with
  // the printed (31) ("v̇1 as printed in (31), with a3·ω_d") are each named.
  holds: [],
  givens: [
    // Names of the walkthrough's steps.
    'under step 1 and write v1',
    'write v2 under step 2 (with the paper’s v1 or yours), v3 under step 3 and v4 under step 4',
    'as the walkthrough’s step 2 does',
    'the verdict of step 2',
    // k1s1 = k1 − a3 of the preset: k1 = 1200 1/s and a3 = Cf/J = 0.001/0.02 = 0.05 1/s
    // (`imlab describe 'v=1&preset=step'`: k1, model.cf, model.j; a3 = Cf/J, k1s1 = k1 − a3).
    'its value on this preset, 1199.95',
  ],
};
