// The lesson The remedy: the rotor resistance as an EKF state, and when it can be seen. Numbers are placeholders of the measurements table
// (web/teaching/measurements/rr-estimate.csv); see web/teaching/measured.js.
export default {
  "id": "rr-estimate",
  "run": "v=1&preset=rr-mismatch-est&duration=4",
  "title": "The remedy: the rotor resistance as an EKF state, and when it can be seen",
  "tab": "walkthrough",
  "look": "The 10 % rotor-resistance mismatch again, over 4 s, this time with R_r as an EKF state (and the RK4 predictor with a small Q). Section 2 of the walkthrough plots R̂_r with its ±2σ band against the motor’s 5.445 Ω. Then set the loads to zero: plant.t0 = model.t0 = 0 and plant.cf = model.cf = 0 in the settings, and run again.",
  "question": "With the load, where does R̂_r go and what is left of the speed error, against the mismatch lesson’s run over the same window? Without any load or friction, what happens to R̂_r and its band, and why?",
  "hint": "At zero slip the rotor flux turns with the stator field and no current flows in the rotor: what does R_r multiply in the model then?",
  "answer": "The R_r state removes the slow transient: at 0.3 s the speed is 0.003 to 0.012 rad/s high instead of 1.2 to 5.1 rad/s low, and within 0.05 rad/s with the motor’s R_r 10 % below the model’s instead or the model’s inertia 20 % off either way. But R̂_r is biased high, with the motor’s R_r 10 % above, equal to or 10 % below the model’s, 1.6 to 3.2 % at 4 s and 2.3 to 3.6 % at 8 s (duration=8) over seeds 1–10, so do not read it as a measurement of R_r to better than a few per cent. At 4 s the speed is 0.017 to 0.030 rad/s high, against 0.087 to 0.089 rad/s low with the same RK4 filter and no R_r state over 6 s. At 8 s the ±2σ band is about ±0.15 Ω, about as wide as the estimate’s error (0.13 to 0.20 Ω): the motor’s value sits at the band’s edge or outside it. With no load and no friction the slip is zero, the rotor current is zero, and R_r, which multiplies rotor current terms, leaves little trace in the stator currents: the band stops shrinking at about ±0.33 Ω, twice its width with the load over the same second to fourth second. R_r is well observable only with slip: load, acceleration or a flux transient."
};
