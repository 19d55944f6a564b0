// What the lessons teach, checked against the core: every number in a lesson's text (title,
// what to look for, question, hint, answer) is either a setting of a run (a "given") or a figure
// that a named run of the native core reproduces within a named tolerance. A number changed in
// the text, or a figure that drifts in the core, fails the test.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { LESSONS, SECTIONS } from '../web/teaching.js';
import { Core, checkText, numbersIn } from './claims.mjs';

const core = new Core();

// Runs the lessons' figures come from (the lesson's own run is `lesson.run`).
const STEP = 'v=1&preset=step';
const STEP_EXACT = 'v=1&preset=step&perfect=1&noise=0';
const SINE = 'v=1&preset=sine200';
const RR = 'v=1&preset=rr-mismatch&duration=6';
const RR_EXACT = 'v=1&preset=rr-mismatch&duration=6&plant.rr=4.95';
const LOAD = 'v=1&preset=load-step&duration=3';
const LOAD_EST = 'v=1&preset=load-step-est';
const RR_EST = 'v=1&preset=rr-mismatch-est&duration=4';
const RR_EST8 = 'v=1&preset=rr-mismatch-est&duration=8';
const RR_EST_NO_LOAD = `${RR_EST}&plant.t0=0&model.t0=0&plant.cf=0&model.cf=0`;
const RAMP = 'v=1&preset=ifoc-step&ref=ramp&ramp.level=40&ramp.slope=200&ramp.hold=5&ifoc.i_max=3.7&duration=1.5';
const RAMP_BS = `${RAMP}&controller=backstepping`;
const IFOC_LOAD = 'v=1&preset=load-step&controller=ifoc&load.time=1&duration=2';
const BS_LOAD = 'v=1&preset=load-step&load.time=1&duration=2';
const DRIVE = 'v=1&preset=sine200-drive';
const HIGH = 'v=1&preset=high-gain';
const LOW = 'v=1&preset=rr-mismatch&ref.value=1&ekf=rk4&init_err=0&duration=3';
/** high-gain with all four gains at `k` (1/s). */
const gains = (k) => `${HIGH}&k1=${k}&k2=${k}&k3=${k}&k4=${k}`;

/** Time constant of the slow mode of `run`'s speed error between t0 and t1 (s), about its final value. */
function slowMode(m, run, t0, t1) {
  const end = m.fig(run, 'speed_error_final');
  return (t1 - t0) / Math.log((m.at(run, 'omega_err', t0) - end) / (m.at(run, 'omega_err', t1) - end));
}

// Per lesson (by title): the numbers that are settings, and the checks of the rest:
// [text as written, tolerance, measured value] or [text, 'claim', a test that must hold].
// Tolerances are a unit of the last digit written, unless a comment says why more.
const SPECS = {
  'The paper’s step response': {
    givens: ['0.5 rad/s', '200 Hz', '50 ms', '45–65 ms', '2 %', '0.1 s', 'perfect=1&noise=0', 'k1 to 600', 'model.j = 0.024', '20 %', 'duration=1', '1 s'],
    checks: [
      ['4.6', 0.05, (m) => 1e3 * m.fig(STEP_EXACT, 'settling_time')],
      ['4.7', 0.05, (m) => 1e3 * m.fig(STEP, 'settling_time')],
      ['one to two samples, 0.1 ms at most', 'claim', (m) => {
        const added = m.fig(STEP, 'settling_time') - m.fig(STEP_EXACT, 'settling_time');
        return added > 0.9 * 5e-5 && added < 2.1 * 5e-5;
      }],
      ['4.7', 0.05, (m) => 1e3 * m.fig(STEP, 'tracking_peak')],
      ['8.2', 0.05, (m) => 1e3 * m.fig(`${STEP}&k1=600`, 'tracking_peak')],
      ['4.7', 0.05, (m) => 1e3 * m.fig(`${STEP}&k1=600`, 'settling_time')],
      ['1.7', 0.05, (m) => m.fig(`${STEP}&k1=600`, 'tracking_peak') / m.fig(STEP, 'tracking_peak')],
      ['0.022', 0.0005, (m) => m.fig(`${STEP}&model.j=0.024`, 'speed_error_final')],
      ['no settling time', 'claim', (m) => m.fig(`${STEP}&model.j=0.024`, 'settling_time') === undefined],
      ['almost all of it the estimate’s error', 'claim', (m) => {
        const [speed, estimate] = ['speed_error_final', 'speed_estimate_error_final'].map((n) => m.fig(`${STEP}&model.j=0.024`, n));
        return Math.abs(estimate - speed) < 0.1 * Math.abs(speed);
      }],
      ['77', 0.5, (m) => 1e3 * m.fig(`${STEP}&model.j=0.024&duration=1`, 'settling_time')],
      ['3.35', 0.005, (m) => 1e3 * m.fig(`${STEP}&model.j=0.024&duration=1&perfect=1`, 'settling_time')],
    ],
  },
  'Why 200 Hz tracking needs a small amplitude': {
    givens: ['200 Hz', '1 rad/s', '±400 V', '0.25 s', '4 A', '0.5 rad/s', 'duration=2', '2 s', '50 ms', '1 s', 'vmax=100000', 'init_err=0'],
    checks: [
      ['16', 0.5, (m) => 100 * m.fig('v=1&preset=sine200-1rad', 'saturated_share')],
      ['0.063', 0.0005, (m) => m.fig('v=1&preset=sine200-1rad', 'tracking_rms')],
      ['no sample is at the limit', 'claim', (m) => m.fig(SINE, 'saturated_share') === 0],
      ['0.016', 0.0005, (m) => m.fig(SINE, 'tracking_rms')],
      ['four times the error', 'claim', (m) => Math.abs(m.fig('v=1&preset=sine200-1rad', 'tracking_rms') / m.fig(SINE, 'tracking_rms') - 4) < 0.25],
      ['4.5', 0.05, (m) => m.fig('v=1&preset=sine200-1rad&vmax=100000&init_err=0', 'tracking_rms') / m.fig(`${SINE}&init_err=0`, 'tracking_rms')],
      ['without any limit', 'claim', (m) => m.fig('v=1&preset=sine200-1rad&vmax=100000&init_err=0', 'saturated_share') === 0],
      ['2', 0.05, (m) => m.fig('v=1&preset=sine200-1rad&vmax=100000&init_err=0&ekf=rk4', 'tracking_rms') / m.fig(`${SINE}&init_err=0&ekf=rk4`, 'tracking_rms')],
      ['32', 0.5, (m) => 100 * m.fig('v=1&preset=sine200-1rad&duration=2', 'saturated_share')],
      ['14.3', 0.05, (m) => m.fig('v=1&preset=sine200-1rad', 'current_peak')],
      ['3.6', 0.05, (m) => m.fig('v=1&preset=sine200-1rad', 'current_peak') / m.fig(SINE, 'current_rated')],
      ['7.5', 0.05, (m) => m.fig(SINE, 'current_peak')],
      ['1.9', 0.05, (m) => m.fig(SINE, 'current_peak') / m.fig(SINE, 'current_rated')],
      // "About 0.28 rad/s is the largest amplitude within 4 A": 0.27 stays within, 0.29 does not.
      ['0.28', 'claim', (m) => m.peakCurrent(`${SINE}&sine.amp=0.27&duration=1`, 0.05) < 4 && m.peakCurrent(`${SINE}&sine.amp=0.29&duration=1`, 0.05) > 4
        && Math.abs(m.peakCurrent(`${SINE}&sine.amp=0.28&duration=1`, 0.05) - 4) < 0.02],
    ],
  },
  'Observer bias: Euler against RK4': {
    givens: ['95 %', 'a mean of 2', '(2.)', '0.25 s', '50 µs', '200 Hz'],
    checks: [
      ['35', 0.5, (m) => m.fig(SINE, 'mean_nis')],
      ['1.94', 0.005, (m) => m.fig(SINE, 'mean_nis_low')],
      ['2.06', 0.005, (m) => m.fig(SINE, 'mean_nis_high')],
      ['1.9', 0.05, (m) => m.fig(`${SINE}&ekf=rk4`, 'mean_nis')],
      ['a little below the band', 'claim', (m) => m.fig(`${SINE}&ekf=rk4`, 'mean_nis') < m.fig(`${SINE}&ekf=rk4`, 'mean_nis_low')
        && m.fig(`${SINE}&ekf=rk4`, 'mean_nis') > m.fig(`${SINE}&ekf=rk4`, 'mean_nis_low') - 0.1],
      ['0.016', 0.0005, (m) => m.fig(SINE, 'tracking_rms')],
      ['0.0063', 0.00005, (m) => m.fig(`${SINE}&ekf=rk4`, 'tracking_rms')],
      ['0.013', 0.0005, (m) => m.stat(SINE, 'omega_err', 0.05, 0.25).mean],
      ['the speed estimate’s own offset', 'claim', (m) => Math.abs(m.stat(SINE, 'omega_err', 0.05, 0.25).mean - m.stat(SINE, 'omega_est_err', 0.05, 0.25).mean) < 0.001],
      ['most of the RMS', 'claim', (m) => m.stat(SINE, 'omega_err', 0.05, 0.25).mean ** 2 > 0.5 * m.stat(SINE, 'omega_err', 0.05, 0.25).rms ** 2],
    ],
  },
  'Rotor-resistance mismatch: a slow transient, then a small bias': {
    givens: ['10 %', '50 rad/s', '6 s', '0.3 s', '1 s', 'plant.rr = 4.95', '1200/s', 'ekf.q=0.01', 'init_err=0'],
    checks: [
      ['5.0', 0.05, (m) => -m.at(RR, 'omega_err', 0.3)],
      ['10', 0.5, (m) => m.fig('v=1&preset=rr-mismatch', 'speed_error_final_rate')],
      ['still changing at the preset’s end', 'claim', (m) => m.fig('v=1&preset=rr-mismatch', 'speed_error_final_settled') === 0],
      ['1.4', 0.05, (m) => -m.at(RR, 'omega_err', 1)],
      ['0.12', 0.005, (m) => m.fig(RR, 'speed_error_final')],
      ['settled', 'claim', (m) => m.fig(RR, 'speed_error_final_settled') === 1],
      ['0.6', 0.05, (m) => slowMode(m, RR, 0.3, 1)],
      ['0.14', 0.005, (m) => -m.at(RR_EXACT, 'omega_err', 0.3)],
      ['0.07', 0.005, (m) => m.at(`${RR}&init_err=0`, 'omega_err', 0.3)],
      ['0.74', 0.005, (m) => -m.at(`${RR}&ekf.q=0.01`, 'omega_err', 1)],
      ['0.21', 0.005, (m) => m.fig(RR_EXACT, 'speed_error_final')],
      ['−0.09', 0.005, (m) => m.fig(RR, 'speed_error_final') - m.fig(RR_EXACT, 'speed_error_final')],
      ['−0.087', 0.0005, (m) => m.fig(`${RR}&ekf=rk4`, 'speed_error_final')],
      ['0.006', 0.0005, (m) => m.fig(`${RR_EXACT}&ekf=rk4`, 'speed_error_final')],
    ],
  },
  'An unknown load step': {
    givens: ['0.15 s', '2 N m', '3 s', '0.3 s', '0.5 s', 'perfect = 1', '50 rad/s', '5-state', 'ekf.q_speed=1e7', '1e6', '1e8', '0.5 rad/s'],
    checks: [
      ['falls for about a second', 'claim', (m) => Math.abs(m.at(LOAD, 'omega_err', 1) - m.fig(LOAD, 'speed_error_final')) < 1 && m.fig(LOAD, 'speed_error_final_settled') === 1],
      ['11', 0.5, (m) => -m.at(LOAD, 'omega_err', 0.3)],
      ['19', 0.5, (m) => -m.at(LOAD, 'omega_err', 0.5)],
      ['25.4', 0.05, (m) => -m.fig(LOAD, 'speed_error_final')],
      ['−25.4', 0.05, (m) => m.fig(LOAD, 'speed_estimate_error_final')],
      ['56', 0.5, (m) => m.fig(LOAD, 'mean_nis')],
      ['0.17', 0.005, (m) => -m.fig(`${LOAD}&perfect=1`, 'speed_error_final')],
      // ΔT/J·(1/k1 + 1/k2) with the run's 2 N m, J = 0.02 kg m² and k1 = k2 = 1200/s.
      ['ΔT/J·(1/k1 + 1/k2)', 'claim', (m) => Math.abs(-m.fig(`${LOAD}&perfect=1`, 'speed_error_final') - (2 / 0.02) * (2 / 1200)) < 1e-3],
      ['0.09', 0.005, (m) => m.stat(`${LOAD}&ekf.q_speed=1e7`, 'omega_err', 2, 3).rms],
      ['2.3', 0.05, (m) => m.stat(`${LOAD}&ekf.q_speed=1e6`, 'omega_err', 2, 3).rms],
      ['0.6', 0.05, (m) => m.stat(`${LOAD}&ekf.q_speed=1e8`, 'omega_err', 2, 3).rms],
      ['0.1', 0.01, (m) => m.recovery(IFOC_LOAD, 1, 0.5)],
    ],
  },
  'The remedy: the load as an EKF state': {
    givens: ['2 N m', '0.15 s', '0.2 s', '0.3 s', '±2σ', 'T0 = 0.5', 'duration=3', '3 s', 'ekf=euler&ekf.q=0.001', 'ekf.rr=1', '0.05 rad/s', '4.95 Ω', 'the last 0.1 s'],
    checks: [
      ['0.16', 0.005, (m) => -m.stat(LOAD_EST, 'omega_err', 0.15, 0.3).min],
      ['6', 0.5, (m) => 1e3 * m.recovery(LOAD_EST, 0.15, 0.05)],
      ['2.5', 0.05, (m) => m.stat(LOAD_EST, 'load_hat', 0.2, 0.3).mean],
      ['0.35', 0.005, (m) => m.at(LOAD_EST, 'load_band', 0.3)],
      ['2.50', 0.005, (m) => m.stat(`${LOAD_EST}&duration=3`, 'load_hat', 2.9, 3).mean],
      ['2.9', 0.05, (m) => -m.fig(`${LOAD_EST}&ekf=euler&ekf.q=0.001`, 'speed_error_final')],
      ['5.50', 0.005, (m) => m.stat(`${LOAD}&ekf.rr=1`, 'rr_hat', 2.9, 3).mean],
      ['23.6', 0.05, (m) => -m.fig(`${LOAD}&ekf.rr=1`, 'speed_error_final')],
      ['49', 0.5, (m) => m.fig(`${LOAD}&ekf.rr=1`, 'mean_nis')],
    ],
  },
  'The remedy: the rotor resistance as an EKF state, and when it can be seen': {
    givens: ['10 %', '4 s', '5.445 Ω', '0.3 s', '±2σ', 'duration=8', '8 s', '0.25–0.3 s and 3.9–4 s', 'plant.t0 = model.t0 = 0', 'plant.cf = model.cf = 0', '6 s'],
    checks: [
      ['0.9', 0.05, (m) => 100 * (m.stat(RR_EST, 'rr_hat', 0.25, 0.3).mean / 5.445 - 1)],
      ['1.7', 0.05, (m) => 100 * (m.stat(RR_EST, 'rr_hat', 3.9, 4).mean / 5.445 - 1)],
      ['3.3', 0.05, (m) => 100 * (m.stat(RR_EST8, 'rr_hat', 7.9, 8).mean / 5.445 - 1)],
      ['0.15', 0.005, (m) => m.stat(RR_EST8, 'rr_band', 7.9, 8).mean],
      ['outside its band', 'claim', (m) => {
        const off = m.stat(RR_EST8, 'rr_hat', 7.9, 8).mean - 5.445;
        const band = m.stat(RR_EST8, 'rr_band', 7.9, 8).mean;
        return off > band && off < 1.5 * band;
      }],
      ['0.008', 0.0005, (m) => m.fig('v=1&preset=rr-mismatch-est', 'speed_error_final')],
      ['5.0', 0.05, (m) => -m.fig('v=1&preset=rr-mismatch', 'speed_error_final')],
      ['0.017', 0.0005, (m) => m.fig(RR_EST, 'speed_error_final')],
      ['0.087', 0.0005, (m) => -m.fig('v=1&preset=rr-mismatch-est&ekf.rr=0&duration=6', 'speed_error_final')],
      ['0.33', 0.02, (m) => m.stat(RR_EST_NO_LOAD, 'rr_band', 1, 4).mean],
      ['stops shrinking', 'claim', (m) => Math.abs(m.stat(RR_EST_NO_LOAD, 'rr_band', 3.5, 4).mean / m.stat(RR_EST_NO_LOAD, 'rr_band', 1, 1.5).mean - 1) < 0.1],
      ['twice its width with the load over the same second to fourth second', 'claim', (m) => Math.abs(m.stat(RR_EST_NO_LOAD, 'rr_band', 1, 4).mean / m.stat(RR_EST, 'rr_band', 1, 4).mean - 2) < 0.25],
    ],
  },
  'The classical baseline, like for like: field-oriented control on the same ramp and current': {
    givens: ['2π·1 kHz', '−2π·50 Hz', '10 Hz', 'Ki = Kp·α_ω/4', '200 rad/s²', '40 rad/s', '3.7 A', '4 A', '0.25 s', '2 %', '0.8 rad/s', 'load.time = 1', 'duration = 2', '20 A', '2 N m', '1 s', '0.5 rad/s', '5-state'],
    checks: [
      ['0.15', 0.005, (m) => m.fig(RAMP_BS, 'tracking_peak')],
      ['its Euler EKF’s slow creep, not the ramp', 'claim', (m) => m.fig(`${RAMP_BS}&ekf=rk4`, 'tracking_peak') < 0.5 * m.fig(RAMP_BS, 'tracking_peak')],
      ['2.8', 0.05, (m) => m.fig(RAMP_BS, 'current_peak')],
      ['7.3', 0.05, (m) => m.fig(RAMP, 'tracking_peak')],
      ['4.0', 0.05, (m) => m.fig(RAMP, 'current_peak')],
      ['within 4 A', 'claim', (m) => m.fig(RAMP, 'current_peak') <= 4 && m.fig(RAMP_BS, 'current_peak') <= 4],
      ['0.34', 0.005, (m) => m.recovery(RAMP, 0.25, 0.8)],
      ['12', 0.5, (m) => 1e3 * m.fig('v=1&preset=ifoc-step&controller=backstepping', 'settling_time')],
      ['43', 0.5, (m) => m.fig('v=1&preset=ifoc-step&controller=backstepping', 'current_peak')],
      ['11', 0.5, (m) => m.fig('v=1&preset=ifoc-step&controller=backstepping', 'current_peak') / 4],
      ['0.33', 0.005, (m) => m.fig('v=1&preset=ifoc-step', 'settling_time')],
      ['1.2', 0.05, (m) => -m.stat(IFOC_LOAD, 'omega_err', 1, 2).min],
      ['0.1', 0.01, (m) => m.recovery(IFOC_LOAD, 1, 0.5)],
      ['0.09', 0.005, (m) => -m.fig(IFOC_LOAD, 'speed_error_final')],
      ['25.4', 0.05, (m) => -m.fig(BS_LOAD, 'speed_error_final')],
    ],
  },
  'Does 200 Hz survive a real drive?': {
    givens: ['delay = 1', '540 V', '312 V', '±400 V', '566 V', 'pwm = 1', '20 kHz', '0.25 s', '4 A', 'delay.comp = 1', '0.1 s', 'model.j = 0.024 and 0.016', '20 %', '0.125 s', '10 %', '50 ms', '200 Hz', '−3 dB'],
    checks: [
      ['0.016', 0.0005, (m) => m.fig(SINE, 'tracking_rms')],
      ['0.024', 0.0005, (m) => m.fig(`${SINE}&delay=1`, 'tracking_rms')],
      ['2', 'claim', (m) => Math.abs(m.fig(DRIVE, 'tracking_rms') / m.fig(`${SINE}&delay=1`, 'tracking_rms') - 1) < 0.02],
      ['0.065', 0.0005, (m) => m.fig(DRIVE, 'ripple_peak')],
      ['0.023', 0.0005, (m) => m.stat(DRIVE, 'omega_err', 0.125, 0.25).rms],
      ['0.016', 0.0005, (m) => m.stat(`${DRIVE}&delay.comp=1`, 'omega_err', 0.125, 0.25).rms],
      ['0.0060', 0.00005, (m) => m.fig(`${DRIVE}&delay.comp=1&ekf=rk4`, 'tracking_rms')],
      ['worse than no compensation at first', 'claim', (m) => m.fig(`${DRIVE}&delay.comp=1`, 'tracking_rms') > m.fig(DRIVE, 'tracking_rms')],
      ['8.8', 0.05, (m) => m.fig(DRIVE, 'current_peak')],
      ['2.2', 0.05, (m) => m.fig(DRIVE, 'current_peak') / 4],
      ['6.8', 0.05, (m) => m.peakCurrent(DRIVE, 0.05)],
      ['1.7', 0.05, (m) => m.peakCurrent(DRIVE, 0.05) / 4],
      ['0.27', 'claim', (m) => m.peakCurrent(`${DRIVE}&sine.amp=0.27&duration=1`, 0.05) < 4 && m.peakCurrent(`${DRIVE}&sine.amp=0.28&duration=1`, 0.05) > 4],
      ['0.015', 0.0005, (m) => m.stat(SINE, 'omega_err', 0.125, 0.25).rms],
      ['0.099', 0.0005, (m) => m.fig(`${DRIVE}&model.j=0.024&perfect=1`, 'tracking_rms')],
      ['0.069', 0.0005, (m) => m.fig(`${DRIVE}&model.j=0.016&perfect=1`, 'tracking_rms')],
      ['0.097', 0.0005, (m) => m.fig(`${DRIVE}&model.j=0.024`, 'tracking_rms')],
      ['0.059', 0.0005, (m) => m.fig(`${DRIVE}&model.j=0.016`, 'tracking_rms')],
      ['0.025', 0.0005, (m) => m.fig(DRIVE, 'tracking_rms')],
      ['3.9', 0.05, (m) => m.fig(`${DRIVE}&model.j=0.024`, 'tracking_rms') / m.fig(DRIVE, 'tracking_rms')],
      ['2.4', 0.05, (m) => m.fig(`${DRIVE}&model.j=0.016`, 'tracking_rms') / m.fig(DRIVE, 'tracking_rms')],
    ],
  },
  'Gains past what the observer supports': {
    givens: ['3000/s', '2.5×', '0.1 s', 'noise 0', 'perfect = 1', '20,000/s', '20 kHz', '1200/s', '1750/s', '1800/s'],
    checks: [
      ['99', 0.5, (m) => 100 * m.fig(HIGH, 'saturated_share')],
      ['99', 0.5, (m) => 100 * m.fig(`${HIGH}&noise=0`, 'saturated_share')],
      ['0.05', 0.005, (m) => 100 * m.fig(`${HIGH}&ekf=rk4`, 'saturated_share')],
      ['337', 0.5, (m) => m.fig(HIGH, 'mean_nis')],
      ['20,000/s works', 'claim', (m) => m.fig(`${STEP}&k1=20000&k2=20000&k3=20000&k4=20000&perfect=1`, 'saturated_share') === 0],
      ['0.95', 0.005, (m) => 100 * m.clippedShare(gains(1200))],
      ['13', 0.5, (m) => 100 * m.clippedShare(gains(1750))],
      ['18', 0.5, (m) => 100 * m.clippedShare(gains(1800))],
      ['30', 'claim', (m) => [1200, 1750, 1800].every((k) => m.lastSaturated(gains(k)) < 0.03)],
      ['0 %', 'claim', (m) => m.fig(gains(1750), 'saturated_share') === 0],
    ],
  },
  'Where sensorless control cannot see: low speed': {
    givens: ['1 rad/s', '3 s', '10 %', 'init_err = 0', '50 rad/s', 'plant.rr = 4.95', 'ref.value = 10', '10 rad/s', '40 ms'],
    checks: [
      ['0.084', 0.0005, (m) => -m.fig('v=1&preset=rr-mismatch&ekf=rk4&init_err=0&duration=3', 'speed_error_final')],
      ['2,000', 'claim', (m) => m.at(LOW, 'omega_hat', 3) > 2000],
      // The last sample of an estimate that swings by tens of rad/s a sample.
      ['−2,500', 60, (m) => m.fig(LOW, 'speed_estimate_error_final')],
      ['32', 0.5, (m) => m.stat(LOW, 'omega', 1, 3).maxAbs],
      ['ran away', 'claim', (m) => m.ranAway(LOW)],
      ['all of the samples in the strip’s window', 'claim', (m) => m.fig(LOW, 'saturated_share') === 1],
      ['77', 0.5, (m) => m.peakCurrent(LOW, 0)],
      ['19', 0.5, (m) => m.peakCurrent(LOW, 0) / 4],
      ['15', 'claim', (m) => m.at(LOW, 'flux_hat', 0.015) - m.at(LOW, 'flux', 0.015) > 0.04 && Math.abs(m.at(LOW, 'omega_hat', 0.015) - 1) < 0.01],
      ['0.70', 0.005, (m) => m.at(LOW, 'flux_hat', 0.015)],
      ['0.65', 0.005, (m) => m.at(LOW, 'flux', 0.015)],
      ['21', 0.5, (m) => 1e3 * m.firstSaturated(LOW)],
      ['only then does ω̂ leave', 'claim', (m) => Math.abs(m.at(LOW, 'omega_hat', 0.021) - 1) < 0.1],
      ['179,000', 2000, (m) => m.fig(LOW, 'mean_nis')],
      ['0.001', 'claim', (m) => Math.abs(m.fig(`${LOW}&plant.rr=4.95`, 'speed_error_final')) < 0.001],
      ['0.083', 0.0005, (m) => -m.fig(LOW.replace('ref.value=1', 'ref.value=10'), 'speed_error_final')],
      ['7', 'claim', (m) => m.ranAway(LOW.replace('ref.value=1', 'ref.value=6.5')) && !m.ranAway(LOW.replace('ref.value=1', 'ref.value=7'))],
      ['with the load or without it', 'claim', (m) => m.ranAway(`${LOW}&plant.t0=0&model.t0=0&plant.cf=0&model.cf=0`)],
      ['tens of webers', 'claim', (m) => m.stat(LOW, 'flux', 2, 3).max > 20],
    ],
  },
};

test('every lesson has its checks, and opens a run the core accepts as written', () => {
  assert.deepEqual(LESSONS.map((l) => l.title).sort(), Object.keys(SPECS).sort());
  for (const lesson of LESSONS) {
    const cli = new URL('../target/release/imlab', import.meta.url).pathname;
    const first = execFileSync(cli, ['describe', lesson.run]).toString().split('\n')[0];
    assert.equal(first, `# ${lesson.run}`, `${lesson.title}: the run is written as the codec writes it`);
  }
});

for (const lesson of LESSONS) {
  test(`lesson: ${lesson.title}`, () => {
    const text = [lesson.title, lesson.look, lesson.question, lesson.hint, lesson.answer].join('\n');
    const problems = checkText(text, SPECS[lesson.title], core);
    assert.deepEqual(problems, []);
  });
}

test('the checks fail when a number in a lesson changes', () => {
  for (const lesson of LESSONS.slice(0, 4)) {
    const spec = SPECS[lesson.title];
    for (const n of new Set(numbersIn(lesson.answer))) {
      // A digit appended: the text no longer states what a given or a check says.
      const changed = lesson.answer.replace(n, `${n}1`);
      assert.notDeepEqual(checkText([lesson.title, lesson.look, lesson.question, lesson.hint, changed].join('\n'), spec, core), [], `${lesson.title}: ${n}`);
    }
  }
  // A measured figure written off by more than its tolerance.
  const spec = { givens: [], checks: [['4.80', 0.005, (m) => 1e3 * m.fig(STEP, 'settling_time')]] };
  assert.notDeepEqual(checkText('settles in 4.80 ms', spec, core), []);
});

// The walkthrough's statements of fact (prose and notes of each section), by section id.
const STEP3 = (m, run) => {
  // ż3 from successive samples against −k3·z3 + z4 averaged over the interval, from the end of
  // step's start-up on (one window for the three runs): the RMS of the difference over the RMS
  // of ż3, in %.
  const tr = m.trace(run);
  const [z3, z4] = [tr.column('z3'), tr.column('z4')];
  const from = m.fig(STEP, 'transient_end');
  let [miss, rate] = [0, 0];
  for (let i = 0; i + 1 < z3.length; i++) {
    if (tr.t[i] < from) continue;
    const d = (z3[i + 1] - z3[i]) / (tr.t[i + 1] - tr.t[i]);
    const model = 0.5 * ((-1200 * z3[i] + z4[i]) + (-1200 * z3[i + 1] + z4[i + 1]));
    miss += (d - model) ** 2;
    rate += d * d;
  }
  return 100 * Math.sqrt(miss / rate);
};
const peakCommand = (m, run) => Math.max(m.stat(run, 'u_a_cmd', 0, 1).maxAbs, m.stat(run, 'u_b_cmd', 0, 1).maxAbs);

const SECTION_SPECS = {
  model: { givens: ['1/J', '3n_pM/(2JL_r)'], checks: [] },
  ekf: { givens: ['(10)', '(11)', '(4)', '±2σ', '95 %', 'averaging 2', '200 Hz', 'Section 3.1'], checks: [] },
  step1: { givens: ['Step 1', '(31)'], checks: [] },
  step2: { givens: ['Step 2', '(32)', '(36)', 'h2²z2/(4ε2)'], checks: [] },
  step3: {
    givens: ['Step 3', '2a10(x2·x̂4 + x3·x̂5)', 'noise=0', 'perfect=1'],
    checks: [
      ['10.1', 0.05, (m) => 1e3 * m.fig(STEP, 'transient_end')],
      ['71', 0.5, (m) => STEP3(m, STEP)],
      ['11', 0.5, (m) => STEP3(m, `${STEP}&noise=0`)],
      ['2.7', 0.05, (m) => STEP3(m, `${STEP}&perfect=1`)],
    ],
  },
  step4: {
    givens: ['Step 4', 'v4 = 2a10·b', '(54)', '(55)', '±400 V', '(48)'],
    checks: [
      ['14', 0.5, (m) => 1e-3 * peakCommand(m, STEP)],
      ['45', 0.5, (m) => 1e-3 * peakCommand(m, 'v=1&preset=rr-mismatch')],
      ['18', 0.5, (m) => 1e3 * m.lastSaturated('v=1&preset=rr-mismatch')],
    ],
  },
  stability: {
    givens: ['(59)', '10 %', 'vmax=100000', 'init_err=0'],
    checks: [
      ['6,287', 0.5, (m) => m.fig('v=1&preset=sine200&vmax=100000', 'speed_error_final')],
      ['9.3', 0.05, (m) => m.fig('v=1&preset=sine200&vmax=100000', 'flux_error_final') + Math.SQRT1_2],
      ['0.013', 0.0005, (m) => m.fig('v=1&preset=sine200&vmax=100000&init_err=0', 'tracking_rms')],
      ['reported as a run that ran away', 'claim', (m) => m.ranAway('v=1&preset=sine200&vmax=100000') && !m.ranAway('v=1&preset=sine200&vmax=100000&init_err=0')],
    ],
  },
};

for (const section of SECTIONS) {
  test(`walkthrough: ${section.title}`, () => {
    const text = [...section.prose, section.note ?? ''].join('\n');
    assert.deepEqual(checkText(text, SECTION_SPECS[section.id], core), []);
  });
}

// The preset descriptions (`imlab list`), by preset. A description speaks of the preset, whatever
// its noise seed: a figure the noise moves is checked over the first four seeds.
const SEEDS = [1, 2, 3, 4];
const overSeeds = (run, holds) => SEEDS.every((seed) => holds(`${run}&seed=${seed}`));
const PRESET_SPECS = {
  // 1.8–2.4 times over seeds 1–8.
  sine200: { givens: ['Fig 2', '0.5 sin(2π·200 t)'], checks: [['about twice', 'claim', (m) => overSeeds(SINE, (run) => Math.abs(m.fig(run, 'current_peak') / m.fig(run, 'current_rated') - 2) < 0.45)]] },
  step: { givens: ['Fig 3', '0 → 0.5 rad/s', '50 ms', '200 Hz'], checks: [] },
  ramp: { givens: ['Fig 4', '100 rad/s', '±400 rad/s²'], checks: [] },
  'sine200-1rad': { givens: ['1 rad/s at 200 Hz', '400 V'], checks: [['saturates', 'claim', (m) => overSeeds('v=1&preset=sine200-1rad', (run) => m.fig(run, 'saturated_share') > 0.1)]] },
  'sine200-rk4': { givens: ['Fig 2', 'rk4'], checks: [] },
  'rr-mismatch': {
    givens: ['50 rad/s', '10 %', '6 s'],
    checks: [
      // 0.48–0.57 s over seeds 1–8: the start-up leaves one of two slow modes.
      ['about half a second', 'claim', (m) => overSeeds(RR, (run) => Math.abs(slowMode(m, run, 0.3, 1) - 0.53) < 0.07)],
      ['ends within 6 s', 'claim', (m) => overSeeds(RR, (run) => m.fig(run, 'speed_error_final_settled') === 1)],
    ],
  },
  'load-step': { givens: ['50 rad/s', '2 N m', '0.15 s', '5-state'], checks: [] },
  decay: { givens: ['ω_d ≡ 0', '1200/s'], checks: [] },
  'ifoc-step': { givens: ['40 rad/s'], checks: [] },
  'load-step-est': { givens: ['rk4'], checks: [['the speed holds', 'claim', (m) => overSeeds(LOAD_EST, (run) => m.stat(run, 'omega_err', 0.15, 0.3).maxAbs < 0.2)]] },
  'rr-mismatch-est': {
    givens: ['rk4', '4 s'],
    // Every sample from the first 50 ms on, in which the estimate leaves its start; the largest
    // excursion is 2.3–3.6 % over seeds 1–6.
    checks: [['4', 'claim', (m) => overSeeds(RR_EST, (run) => {
      const { min, max } = m.stat(run, 'rr_hat', 0.05, 4);
      return Math.abs(max / 5.445 - 1) < 0.04 && Math.abs(min / 5.445 - 1) < 0.04;
    })]],
  },
  'sine200-drive': { givens: ['200 Hz', '540 V'], checks: [] },
  'high-gain': { givens: ['3000/s', '2.5×', '400 V'], checks: [['saturate', 'claim', (m) => overSeeds(HIGH, (run) => m.fig(run, 'saturated_share') > 0.9)]] },
};

test('the preset descriptions', () => {
  const cli = new URL('../target/release/imlab', import.meta.url).pathname;
  const list = execFileSync(cli, ['list']).toString().trim().split('\n').map((l) => l.match(/^(\S+)\s+(.*)$/).slice(1));
  assert.deepEqual(list.map(([name]) => name).sort(), Object.keys(PRESET_SPECS).sort());
  for (const [name, description] of list) assert.deepEqual(checkText(description, PRESET_SPECS[name], core), [], name);
});
