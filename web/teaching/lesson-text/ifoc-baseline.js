// The lesson The classical baseline, like for like: field-oriented control on the same ramp and current. Numbers are placeholders of the measurements table
// (web/teaching/measurements/ifoc-baseline.csv); see web/teaching/measured.js.
export default {
  id: 'ifoc-baseline',
  run: 'v=1&preset=ifoc-step&ref=ramp&ramp.level=40&ramp.slope=200&ramp.hold=5&ifoc.i_max=3.7&duration=1.5',
  plot: 'speed', // the speed falling behind the ramp
  title: 'The classical baseline: field-oriented control on the same ramp',
  look: 'This run uses indirect field-oriented control (IFOC) with a Schauder MRAS speed estimate, tuned by textbook rules: current loops by internal-model control (Kp = α_c·σ, Ki = α_c·R′ with R′ = R_s + (M/L_r)²R_r, α_c = 2π·1 kHz), the MRAS with both poles at −2π·50 Hz and the speed loop at 10 Hz (Kp = α_ω·J/K_t, Ki = Kp·α_ω/4). To compare like with like, both designs get the same reference and the same noise: a ramp at 200 rad/s² to 40 rad/s. The IFOC’s q-current is limited to 3.7 A so that |i_s| stays within the 4 A rating; backstepping has no current limit, so read what it draws. Press “Pin this run”, set controller = backstepping in the settings and run: the overlay shows both.',
  question:
    'On the same ramp, how far does each design fall behind, what peak current does each draw against the 4 A rating, and how long after the ramp ends (at 0.25 s) is the IFOC within 2 % of 40 rad/s for good? What does each do with the motor’s R_r 10 % above the model’s (plant.rr = 5.445)? Which design rejects an unknown load, and why?',
  hint: 'Read “peak |ω − ω_d|” and “peak stator current” for both runs, then again with plant.rr = 5.445; the peak current figure starts after the start-up transient, the |i_s| plot shows the whole run. For the load, open the load-step preset with load.time = 1 and duration = 2, with controller = ifoc and without.',
  answer:
    'Ranges are over {ib.bs.ra#draws} noise draws (seeds 1 to {ib.bs.ra#draws}). With an exact model backstepping follows the ramp far closer than the IFOC, but not within the same current. Backstepping stays within {ib.bs.tp} rad/s of the ramp; its peak stator current after the start-up transient is {ib.bs.ipk.min} to {ib.bs.ipk.max} A, over the 4 A rating on {ib.bs.ipk.over} of {ib.bs.ipk.over#draws} draws, and over the whole run its |i_s| passes 4 A on {ib.bs.all.over} of {ib.bs.all.over#draws} draws, up to {ib.bs.all.ipk} A in the start-up transient. The IFOC’s |i_s| peaks at most at {ib.if.ipk} A over the whole run; it falls up to {ib.if.tp} rad/s behind and is within 2 % (0.8 rad/s) of 40 rad/s for good {ib.if.rec.max} s after the ramp ends. With the motor’s R_r above the model’s backstepping runs away, from the preset’s initial estimate and from a correct one (init_err = 0), on {ib.bs.p4.ra} and {ib.bs.p4.init.ra} of {ib.bs.p4.ra#draws} draws at 4 % above (from the preset’s estimate up to {ib.bs.p4.tp} rad/s behind, up to {ib.bs.p4.ipk} A), on {ib.bs.p5.ra} and {ib.bs.p5.init.ra} at 5 % above, and on {ib.bs.p7.ra} and {ib.bs.p7.init.ra} at 7 % above. A run counts as ran away by its state at the end of the run; the runs that hold at 5 % above from init_err = 0 also stay close on the way, after the start-up transient within {ib.bs.p5.init.tp} rad/s of the ramp at up to {ib.bs.p5.init.ipk} A. With R_r 10 % below the model’s it runs away on {ib.bs.m10.ra} of {ib.bs.m10.ra#draws} draws, up to {ib.bs.m10.tp} rad/s behind at no more than {ib.bs.m10.ipk} A. The IFOC runs away with R_r 10 % high or low on {ib.if.p10.ra} and {ib.if.m10.ra} of {ib.if.p10.ra#draws} draws, up to {ib.if.p10.tp} or {ib.if.m10.tp} rad/s behind, with |i_s| at most {ib.if.m10.ipk} A either way. Under an unknown load the order reverses. A 2 N m step at 1 s takes the IFOC’s speed error down to {ib.il.dip} rad/s at worst, back within 0.5 rad/s for good at most {ib.il.back} s later, ending {ib.il.fin.min} to {ib.il.fin.max} rad/s; the paper’s 5-state design ends with a speed error of {ib.bl.fin.min} to {ib.bl.fin.max} rad/s. The IFOC’s PI speed loop integrates the speed error; the 5-state design has no load state. Given one (ekf.load = 1), the same loop ends {ib.bl.load.fin.min} to {ib.bl.load.fin.max} rad/s, and within {ib.bl.est.fin} rad/s with the RK4 predictor and the process noise of the preset load-step-est; the RK4 predictor without the load state (ekf = rk4) still ends with {ib.bl.rk4.fin.max} rad/s or worse.',
  holds: [
    'ib.bs.ra == 0',
    'ib.if.ra == 0',
    // "far closer": backstepping's largest lag is under a tenth of the IFOC's.
    '10 * ib.bs.tp < ib.if.tp',
    // "passes 4 A on … draws, up to … in the start-up transient".
    'ib.bs.all.over > 0',
    'ib.bs.start.ipk == ib.bs.all.ipk',
    // The IFOC within the 4 A rating over the whole run, exact model and R_r ±10 %.
    'ib.if.ipk < 4',
    'ib.if.p10.ipk < 4',
    'ib.if.m10.ipk < 4',
    // One recovery time for every draw (shown to two digits).
    'ib.if.rec.max - ib.if.rec.min < 0.005',
    // "the runs that hold … from init_err = 0": all of them, so the peaks are theirs.
    'ib.bs.p5.init.ra == 0',
    // "at most … either way".
    'ib.if.p10.ipk <= ib.if.m10.ipk',
    // The load state is the remedy; the RK4 predictor alone is not.
    'ib.bl.load.fin.min > 0.2 * ib.bl.fin.min',
    'ib.bl.est.fin < 0.1',
    'ib.bl.rk4.fin.max < 0.9 * ib.bl.fin.max',
  ],
  givens: [
    'α_c = 2π·1 kHz',
    'poles at −2π·50 Hz',
    'speed loop at 10 Hz',
    'Ki = Kp·α_ω/4',
    'ramp at 200 rad/s² to 40 rad/s',
    'limited to 3.7 A so that |i_s| stays within the 4 A rating',
    'against the 4 A rating',
    'ramp ends (at 0.25 s)',
    'within 2 % of 40 rad/s',
    'R_r 10 % above the model’s (plant.rr = 5.445)',
    'load.time = 1 and duration = 2',
    '5-state design',
    'seeds 1 to',
    'over the 4 A rating on',
    'passes 4 A on',
    'within 2 % (0.8 rad/s) of 40 rad/s',
    'at 4 % above',
    'at 5 % above',
    'at 7 % above',
    'R_r 10 % below',
    'R_r 10 % high or low',
    'A 2 N m step at 1 s',
    'back within 0.5 rad/s',
  ],
};
