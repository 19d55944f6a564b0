//! A student's own laws: the paper's law written in the language reproduces the built-in runs bit
//! for bit, a wrong law is caught by the verdict and named, and a law that gives a non-finite value
//! fails the run with the formula, the time and its signals.

use imlab::control::law::{check, PAPER};
use imlab::scenario::{Scenario, PRESETS};
use imlab::sim::{SimError, Simulation};

fn csv(s: &Scenario) -> (Vec<u8>, Result<(), SimError>) {
    let mut sim = Simulation::traced(s).unwrap();
    let result = sim.run();
    let mut out = Vec::new();
    sim.write_csv(&mut out).unwrap();
    (out, result)
}

fn with_laws(s: &Scenario, steps: &[usize]) -> Scenario {
    let mut s = s.clone();
    for &i in steps {
        s.law[i] = Some(PAPER[i].to_string());
    }
    s
}

#[test]
fn the_papers_law_written_as_formulas_gives_the_built_in_runs_bits() {
    for p in PRESETS {
        let base = Scenario::parse(p.name).unwrap();
        if base.controller != imlab::scenario::ControllerKind::Backstepping {
            continue;
        }
        let (expected, result) = csv(&base);
        for steps in [&[0usize][..], &[1], &[2], &[3], &[0, 1, 2, 3]] {
            let s = with_laws(&base, steps);
            // Through the codec, as a link carries it.
            let s = Scenario::parse(&s.encode()).unwrap();
            let (got, r) = csv(&s);
            assert_eq!(r.is_ok(), result.is_ok(), "{} with steps {steps:?}", p.name);
            assert!(
                got == expected,
                "{} with steps {steps:?}: the CSV differs",
                p.name
            );
        }
    }
}

#[test]
fn with_the_robust_terms_and_the_estimated_load_the_papers_law_still_gives_the_same_bits() {
    for text in [
        "v=1&preset=step&robust=1&h2=5000&h4=2000&duration=0.05",
        "v=1&preset=load-step-est&duration=0.05",
        "v=1&preset=rr-mismatch-est&duration=0.05",
        "v=1&preset=step&delay=1&delay.comp=1&duration=0.05",
        "v=1&preset=step&perfect=1&duration=0.05",
    ] {
        let base = Scenario::parse(text).unwrap();
        let (expected, _) = csv(&base);
        let (got, _) = csv(&with_laws(&base, &[0, 1, 2, 3]));
        assert!(got == expected, "{text}: the CSV differs");
    }
}

#[test]
fn a_link_with_a_law_round_trips_and_a_bad_law_is_refused_at_its_place() {
    let s = Scenario::parse(
        "v=1&preset=step&law.v1=-si1%20%2B%20dwd%20%2B%20a3*wd%20%2B%20a2%20-%20k1s1*z1",
    )
    .unwrap();
    assert_eq!(
        s.law[0].as_deref(),
        Some("-si1 + dwd + a3*wd + a2 - k1s1*z1")
    );
    assert_eq!(Scenario::parse(&s.encode()).unwrap(), s);
    // A `+` is a plus in the codec, not a space.
    let plus = Scenario::parse("v=1&preset=step&law.v3=-k3*z3+0").unwrap();
    assert_eq!(plus.law[2].as_deref(), Some("-k3*z3+0"));
    for (text, needle) in [
        (
            "v=1&preset=step&law.v1=z1%20*",
            "field 'law.v1': at character 5",
        ),
        ("v=1&preset=step&law.v2=foo", "unknown name 'foo'"),
        ("v=1&preset=step&law.v1=z2", "not known in step 1"),
        ("v=1&preset=step&law.v1=1/0", "division by zero"),
        ("v=1&preset=step&law.v1=%FF", "field 'law.v1'"),
    ] {
        let e = Scenario::parse(text).unwrap_err().to_string();
        assert!(e.contains(needle), "{text}: {e}");
    }
    // Leniently, the rest of the scenario is kept and the bad law alone is left out.
    let (s, errors) = Scenario::parse_lenient("v=1&preset=step&k1=900&law.v2=foo").unwrap();
    assert_eq!((s.gains.k1, s.law[1].clone()), (900.0, None));
    assert_eq!(errors.len(), 1);
}

/// The message of the run of `s`, which must fail.
fn failure(s: &Scenario) -> String {
    Simulation::traced(s)
        .unwrap()
        .run()
        .unwrap_err()
        .to_string()
}

#[test]
fn a_law_that_gives_a_non_finite_value_fails_the_run_with_its_formula_time_and_signals() {
    let s = Scenario::parse("v=1&preset=step&law.v3=-k3*z3%20%2B%20ln(z3%20-%20z3)").unwrap();
    let e = failure(&s);
    assert!(
        e.starts_with("your law.v3 = -k3*z3 + ln(z3 - z3) gave -inf at t = 0.00000 s, from k3 = "),
        "{e}"
    );
    assert!(e.contains("z3 = "), "{e}");
    // A law that reads no signal says so.
    let s = Scenario::parse("v=1&preset=step&law.v1=ln(0%20-%201)").unwrap();
    assert_eq!(
        failure(&s),
        "your law.v1 = ln(0 - 1) gave NaN at t = 0.00000 s, reading no signal"
    );
}

#[test]
fn a_finite_law_that_drives_a_papers_step_past_every_bound_ends_the_run_as_diverged() {
    // v1 = 1e306 is finite; the paper's step 2 then is not, and the voltage it asks for is refused.
    let s = Scenario::parse("v=1&preset=step&law.v1=1e306").unwrap();
    let e = failure(&s);
    assert!(
        e.contains("diverged") || e.contains("controller failed"),
        "{e}"
    );
}

/// The verdict of step `step` written as `text`, the other steps the paper's.
fn verdict(step: u8, text: &str) -> imlab::control::law::Verdict {
    chain(&[(step, text)]).pop().unwrap()
}

/// The verdicts of the steps written in `laws`, the other steps the paper's, on `step`.
fn chain(laws: &[(u8, &str)]) -> Vec<imlab::control::law::Verdict> {
    let s = Scenario::parse("step").unwrap();
    let mut texts: [Option<String>; 4] = Default::default();
    for (step, text) in laws {
        texts[*step as usize - 1] = Some(text.to_string());
    }
    laws.iter()
        .map(|(step, _)| check(*step, &texts, &s.model.lumped().unwrap(), &s.gains).unwrap())
        .collect()
}

#[test]
fn the_papers_law_gets_the_designed_dynamics_and_each_common_mistake_is_named() {
    for step in 1..=4u8 {
        let v = verdict(step, PAPER[step as usize - 1]);
        assert!(v.designed, "{}", v.text);
    }
    // The paper's law rearranged is the same law.
    assert!(verdict(1, "dwd - si1 + a2 + a3*x1h - k1*z1").designed);
    let cases: &[(u8, &str, &str)] = &[
        (1, "-si1 + dwd + a3*wd + a2 - k1*z1", "k1 where (28) has k1s1"),
        (1, "-si1 + dwd + a3*x1h + a2 - k1s1*z1", "a3·x̂1 where (27) has a3·ω_d"),
        (1, "si1 + dwd + a3*wd + a2 - k1s1*z1", "the term −si1 has the wrong sign"),
        (1, "dwd + a3*wd + a2 - k1s1*z1", "the term −si1 of the paper's law is missing"),
        (1, "-si1 + dwd + a3*wd + a2 - 400*z1", "decays at 400 /s, not 1200 /s"),
        // step's k1s1 = 1200 − 0.05 written as its number: right here, wrong for other values.
        (1, "-si1 + dwd + a3*wd + a2 - 1199.95*z1", "written as its number"),
        // A missing term is named with one sign, its own minus folded in.
        (
            3,
            "-(-2*a8*(x4h*x4h + x5h*x5h) + 2*(x4h*si4 + x5h*si5)) - k3*z3",
            "the term +2·a10·(xt2·x4h + xt3·x5h) of the paper's law is missing",
        ),
        (
            3,
            "-(-2*a8*(x4h*x4h + x5h*x5h) - 2*a10*(xt2*x4h + xt3*x5h)) - k3*z3",
            "the term −2·(x4h·si4 + x5h·si5) of the paper's law is missing",
        ),
        (
            3,
            "-(-2*a10*(xt2*x4h + xt3*x5h) + 2*(x4h*si4 + x5h*si5)) - k3*z3",
            "the term +2·a8·(x4h·x4h + x5h·x5h) of the paper's law is missing",
        ),
        (
            3,
            "-(-2*a8*(x4h*x4h + x5h*x5h) - 2*a10*(xt2*x4h + xt3*x5h) + 2*(x4h*si4 + x5h*si5)) - k3*(x4h*x4h + x5h*x5h - psi_d*psi_d)",
            "ψ_d as the flux modulus",
        ),
    ];
    for (step, text, needle) in cases {
        let v = verdict(*step, text);
        assert!(!v.designed, "{text}: {}", v.text);
        assert!(v.text.to_string().contains(needle), "{text}: {}", v.text);
    }
    // n_p = a9 = 2 on the paper's motor: a law that writes one for the other is refused.
    let swapped = PAPER[2].replace("-2*a8", "-a9*a8");
    assert!(!verdict(3, &swapped).designed);
    // Step 2: a missing −z1, k2 for k2s1 and the printed (31)'s typos.
    let v2 = PAPER[1];
    let missing_z1 = v2.replace(")) - z1 +", ")) +");
    assert_ne!(missing_z1, v2);
    assert!(verdict(2, &missing_z1)
        .text
        .to_string()
        .contains("−z1 of the paper's law is missing"));
    assert!(verdict(2, &v2.replace("(-k2s1*z2", "(-k2*z2"))
        .text
        .to_string()
        .contains("k2 where (36) has k2s1"));
    let mut texts: [Option<String>; 4] = Default::default();
    texts[1] = Some(v2.replace(" + -robust*h2*h2/(4*eps2)*z2", ""));
    let robust = imlab::control::law::check(
        2,
        &texts,
        &Scenario::parse("step").unwrap().model.lumped().unwrap(),
        &Scenario::parse("v=1&preset=step&robust=1").unwrap().gains,
    )
    .unwrap();
    assert!(
        robust
            .text
            .to_string()
            .contains("the term −robust·h2·h2/(4·eps2)·z2 of the paper's law is missing"),
        "{}",
        robust.text
    );
    assert!(verdict(2, &v2.replace("a3*dwd", "a3*wd"))
        .text
        .to_string()
        .contains("printed in (31)"));
    // Step 4: a missing −z3 and the forgotten k3·(−k3·z3 + z4).
    let v4 = PAPER[3];
    assert!(verdict(4, &v4.replace(") - z3 +", ") +"))
        .text
        .to_string()
        .contains("−z3 of the paper's law is missing"));
    let no_k3 = v4.replace("+ k3*(-k3*z3 + z4))", ")");
    assert_ne!(no_k3, v4);
    let v = verdict(4, &no_k3);
    assert!(
        v.text
            .to_string()
            .contains("the term −k3·(−k3·z3 + z4) of the paper's law is missing"),
        "{}",
        v.text
    );
}

#[test]
fn slips_inside_a_term_and_across_a_step_are_named() {
    let v2 = PAPER[1];
    // The printed (31) copied whole, both typos at once.
    assert!(verdict(2, &v2.replace("a3*dwd + da2", "a3*wd + a2"))
        .text
        .to_string()
        .contains("with both of its typos"));
    // The robust terms written without their switch, which is off on `step`.
    assert!(verdict(2, &v2.replace("-robust*h2", "-h2"))
        .text
        .to_string()
        .contains("without the switch robust"));
    assert!(verdict(4, &PAPER[3].replace("-robust*h4", "-h4"))
        .text
        .to_string()
        .contains("without the switch robust"));
    // Step 3: the factor 2 dropped throughout, and one injection missing.
    let v3 = PAPER[2];
    let halved = v3
        .replace("-2*a8", "-a8")
        .replace("- 2*a10", "- a10")
        .replace("+ 2*(x4h", "+ (x4h");
    assert!(verdict(3, &halved)
        .text
        .to_string()
        .contains("drops the factor 2 throughout ψ3"));
    let one = verdict(3, &v3.replace("2*(x4h*si4 + x5h*si5)", "2*(x4h*si4)"));
    assert!(
        one.text.to_string().contains(
            "the part −2·x5h·si5 of the term −2·(x4h·si4 + x5h·si5) of the paper's law is missing"
        ),
        "{}",
        one.text
    );
    // Step 4: half of k3·(−k3·z3 + z4), f̂4 for x̂̇4 and si4 missing from the factor of x̂̇4.
    let half = verdict(4, &PAPER[3].replace("k3*(-k3*z3 + z4)", "k3*z4"));
    assert!(
        half.text
            .to_string()
            .contains("the part +k3·k3·z3 of the term"),
        "{}",
        half.text
    );
    let drift = PAPER[3]
        .replace("*dx4h", "*(-a8*x4h - a9*x1h*x5h + a10*x2h)")
        .replace("*dx5h", "*(-a8*x5h + a9*x1h*x4h + a10*x3h)");
    assert!(verdict(4, &drift)
        .text
        .to_string()
        .contains("the model's drifts f̂4, f̂5"));
    assert!(
        verdict(4, &PAPER[3].replace("2*(si4 + a10*x2h", "2*(a10*x2h"))
            .text
            .to_string()
            .contains("the factor of x̂̇4 leaves out si4")
    );
}

#[test]
fn step_2_and_step_4_are_judged_on_the_students_own_earlier_step() {
    // k1 where (28) has k1s1: then ż1 = −(k1 + a3)·z1 + z2, and a v2 that differentiates this v1
    // with that ż1 gives step 2's designed dynamics.
    let v1 = "-si1 + dwd + a3*wd + a2 - k1*z1";
    let v2 = PAPER[1].replace("-k1s1*(-k1*z1 + z2)", "-k1*(-(k1 + a3)*z1 + z2)");
    let [one, two] = <[_; 2]>::try_from(chain(&[(1, v1), (2, &v2)])).unwrap();
    assert!(
        !one.designed && one.text.to_string().contains("k1 where (28) has k1s1"),
        "{}",
        one.text
    );
    assert!(
        two.designed && two.text.to_string().contains("with your own v1"),
        "{}",
        two.text
    );
    // The paper's v2 after that v1 differentiates the paper's v1, not the student's.
    let paper_after = chain(&[(1, v1), (2, PAPER[1])]).pop().unwrap();
    assert!(!paper_after.designed, "{}", paper_after.text);
    // After the paper's v1 written as the student's own, the paper's v2 holds.
    let both = chain(&[(1, "dwd - si1 + a2 + a3*x1h - k1*z1"), (2, PAPER[1])]);
    assert!(both.iter().all(|v| v.designed), "{both:?}");
    // Step 4 on a v3 with twice the gain: ż3 = −2·k3·z3 + z4.
    let v3 = PAPER[2].replace("- k3*z3", "- 2*k3*z3");
    let v4 = PAPER[3].replace("k3*(-k3*z3 + z4)", "2*k3*(-2*k3*z3 + z4)");
    let [three, four] = <[_; 2]>::try_from(chain(&[(3, &v3), (4, &v4)])).unwrap();
    assert!(!three.designed, "{}", three.text);
    assert!(
        four.designed && four.text.to_string().contains("with your own v3"),
        "{}",
        four.text
    );
    // A v1 with no finite value at some drawn states (ln of a speed drawn either side of zero):
    // step 2 is judged where it has one, and says so.
    let v1 = "-si1 + dwd + a3*wd + a2 - k1s1*z1 + 0*ln(x1h)";
    let two = chain(&[(1, v1), (2, PAPER[1])]).pop().unwrap();
    assert!(
        two.text.to_string().contains("gives no finite value at"),
        "{}",
        two.text
    );
    // A v1 whose rate needs the voltage (it reads x2): step 2 is judged on the paper's v1, and
    // says so.
    let v1 = "-si1 + dwd + a3*wd + a2 - k1s1*z1 + 0*x2";
    let two = chain(&[(1, v1), (2, PAPER[1])]).pop().unwrap();
    assert!(
        two.designed && two.text.to_string().contains("reads x2"),
        "{}",
        two.text
    );
}

#[test]
fn a_challenge_allows_a_law_and_grades_it_by_its_residual_like_any_other_field() {
    use imlab::challenge::grade::grade_one;
    use imlab::challenge::Challenge;
    let text = "c=1&title=Derive%20step%201&base=v%3D1%26preset%3Dstep%26duration%3D0.05\
                &allow.law.v1=formula&need.law_residual=max:1e-9";
    let c = Challenge::parse(text).unwrap();
    let brief = c.brief().to_string();
    assert!(brief.contains("law.v1"), "{brief}");
    let pct = |t: &str| t.bytes().map(|b| format!("%{b:02X}")).collect::<String>();
    let submit = |law: &str| grade_one(&c, 1, &format!("{text}&try.law.v1={}", pct(law)));
    let right = submit(PAPER[0]);
    assert!(right.pass(), "{right:?}");
    // The same law rearranged passes; k1 for k1s1 is off by a part in a few hundred thousand,
    // and fails.
    assert!(submit("dwd - si1 + a2 + a3*x1h - k1*z1").pass());
    let wrong = submit("-si1 + dwd + a3*wd + a2 - k1*z1");
    assert!(
        !wrong.pass() && wrong.status.to_string() == "ok",
        "{wrong:?}"
    );
    // A gain written as its number is right on this motor only: the check's drawn parameter
    // values fail it, as they fail the verdict.
    let number = submit("-si1 + dwd + a3*wd + a2 - 1199.95*z1");
    assert!(
        !number.pass() && number.status.to_string() == "ok",
        "{number:?}"
    );
    // A formula that does not parse is refused with the field and the reason.
    let bad = submit("-si1 + foo");
    let status = bad.status.to_string();
    assert!(
        status.contains("law.v1") && status.contains("foo"),
        "{status}"
    );
    // No law at all has no residual to judge: it does not pass.
    assert!(!grade_one(&c, 1, text).pass());
    // A law is allowed only as a formula.
    let e = Challenge::parse(&text.replace("allow.law.v1=formula", "allow.law.v1=1..2"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("allow.law.v1=formula"), "{e}");
}

#[test]
fn a_run_judges_step_2_on_the_students_own_v1_as_the_verdict_does() {
    let pct = |t: &str| t.bytes().map(|b| format!("%{b:02X}")).collect::<String>();
    // z1 decaying at k1 − 100 /s: a v1 off by 100·z1, which the run's step changes a lot.
    let v1 = "-si1 + dwd + a3*wd + a2 - k1s1*z1 + 100*z1";
    let largest_r2 = |v2: &str| {
        let link = format!(
            "v=1&preset=step&duration=0.05&law.v1={}&law.v2={}",
            pct(v1),
            pct(v2)
        );
        let mut sim = Simulation::traced(&Scenario::parse(&link).unwrap()).unwrap();
        sim.run().unwrap();
        // Columns t, r1, r2, r3, r4.
        let columns = sim.law_residuals(0.0, 0.05, 200).unwrap();
        columns[2].iter().fold(0.0f64, |m, r| m.max(r.abs()))
    };
    let own =
        largest_r2(&PAPER[1].replace("-k1s1*(-k1*z1 + z2)", "-(k1s1 - 100)*(-(k1 - 100)*z1 + z2)"));
    // The paper's v2 differentiates the paper's v1: its residual is the chain's correction.
    let paper = largest_r2(PAPER[1]);
    assert!(paper > 0.0 && own <= 1e-6 * paper, "{own} against {paper}");
}

#[test]
fn each_steps_error_dynamics_follows_its_design_to_the_sampling_error() {
    // With the perfect observer, no noise and an exact model, ż_i = −k_i·z_i + coupling holds in
    // continuous time; the sampled loop misses it by about k_i·Ts of its size (a forward
    // difference of e^(−kt) is off by k·Ts/2), so twice that bounds it. A wrong coupling or gain
    // in the designed rate would miss by its own size.
    // With the robust terms on (ε sized so each adds 1200/s), the designed rate holds them: a
    // designed rate without them would miss by the robust term's share of it.
    for text in [
        "v=1&preset=step&duration=0.05&perfect=1&noise=0",
        "v=1&preset=step&duration=0.05&perfect=1&noise=0&robust=1&h2=5000&h4=2000&eps2=5208&eps4=833",
    ] {
        let s = Scenario::parse(text).unwrap();
        let mut sim = Simulation::traced(&s).unwrap();
        sim.run().unwrap();
        let c = sim.designed_dynamics(0.0, 0.05, 100_000).unwrap();
        assert_eq!(c[0].len(), sim.len(), "every sample");
        // A window ends where the plots' windows end: its last sample is there.
        let w = sim.designed_dynamics(0.01, 0.02, 100_000).unwrap();
        let main = sim.view(&[vec!["t".to_string()]], 0.01, 0.02, 100_000).unwrap();
        assert_eq!((w[0][0], w[0].last()), (main[0][0][0], main[0][0].last()));
        for step in 1..=4u8 {
            let i = step as usize - 1;
            let k = s.gains.designed_rate(step);
            let (rate, designed) = (&c[1 + 2 * i], &c[2 + 2 * i]);
            let size = designed.iter().fold(0.0f64, |m, d| m.max(d.abs()));
            let miss = rate
                .iter()
                .zip(designed)
                .fold(0.0f64, |m, (r, d)| m.max((r - d).abs()));
            assert!(
                size > 0.0 && miss <= 2.0 * k * s.ts * size,
                "{text}, step {step}: misses by {miss} of {size}"
            );
        }
    }
    // The IFOC baseline's errors are not designed to a rate.
    let ifoc = Simulation::traced(
        &Scenario::parse("v=1&preset=step&controller=ifoc&duration=0.01").unwrap(),
    )
    .unwrap();
    assert!(ifoc.designed_dynamics(0.0, 0.01, 10).is_err());
}

#[test]
fn the_run_figure_takes_the_verdicts_worst_difference() {
    let s = Scenario::parse("step").unwrap();
    let model = s.model.lumped().unwrap();
    let v2 = PAPER[1].replace("-k1s1*(-k1*z1 + z2)", "-k1*(-(k1 + a3)*z1 + z2)");
    for laws in [
        [
            Some("-si1 + dwd + a3*wd + a2 - k1*z1".to_string()),
            Some(v2),
            None,
            None,
        ],
        [
            None,
            None,
            Some(PAPER[2].replace("-2*a8", "-a9*a8")),
            Some(PAPER[3].to_string()),
        ],
    ] {
        let verdicts = imlab::control::law::verdicts(&laws, &model, &s.gains).unwrap();
        let largest = verdicts
            .iter()
            .map(|v| v.worst.unwrap())
            .fold(0.0, f64::max);
        assert_eq!(
            imlab::control::law::worst(&laws, &model, &s.gains),
            Some(Ok(largest))
        );
        assert!(largest > 1e-9);
    }
}

/// A v1 that is the paper's plus a term that overflows where z1 is large: finite on a run from
/// rest, not at every drawn state.
const OVERFLOWS: &str = "-si1 + dwd + a3*wd + a2 - k1s1*z1 + exp(10*abs(z1)) - 1";

#[test]
fn a_law_not_finite_at_a_drawn_state_fails_its_verdict_with_the_cause() {
    let s = Scenario::parse("step").unwrap();
    let model = s.model.lumped().unwrap();
    let verdict = |law: &str| {
        let laws = [Some(law.to_string()), None, None, None];
        check(1, &laws, &model, &s.gains).unwrap()
    };
    let v = verdict(OVERFLOWS);
    assert!(!v.designed && v.worst.is_none(), "{v:?}");
    assert!(
        v.text
            .to_string()
            .contains("your v1 (rad/s²) is not a finite number at ")
            && v.text
                .to_string()
                .contains(" of the 200 drawn states: it gives inf at ")
            && v.text.to_string().contains("z1 = "),
        "{}",
        v.text
    );
    // Nowhere a number: a law that reads no signal says so.
    let v = verdict("exp(1000)");
    assert!(
        v.text
            .to_string()
            .contains("at 200 of the 200 drawn states: it gives inf, reading no signal"),
        "{}",
        v.text
    );
    assert!(!v.text.to_string().contains("up to inf"), "{}", v.text);
}

#[test]
fn a_law_residual_that_is_not_finite_fails_the_metrics_and_a_criterion_with_its_cause() {
    use imlab::challenge::grade::grade_one;
    use imlab::challenge::Challenge;
    let pct = |t: &str| t.bytes().map(|b| format!("%{b:02X}")).collect::<String>();
    let scenario = format!("v=1&preset=step&duration=0.02&law.v1={}", pct(OVERFLOWS));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_imlab"))
        .args(["metrics", scenario.as_str()])
        .output()
        .unwrap();
    let (stdout, stderr) = (
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr),
    );
    assert!(!out.status.success(), "{stdout}");
    assert!(
        !stdout.contains("inf") && !stdout.contains("law_residual"),
        "{stdout}"
    );
    assert!(stdout.contains("tracking_rms,"), "{stdout}");
    assert!(
        stderr.contains(
            "law_residual is not a finite number: your v1 (rad/s²) is not a finite number at "
        ),
        "{stderr}"
    );
    // Graded: the criterion on it fails with the cause; the others are judged as usual.
    let text = "c=1&title=Derive&base=v%3D1%26preset%3Dstep%26duration%3D0.02\
                &allow.law.v1=formula&need.law_residual=max:1e-9&need.current_peak=max:100";
    let c = Challenge::parse(text).unwrap();
    let graded = grade_one(&c, 1, &format!("{text}&try.law.v1={}", pct(OVERFLOWS)));
    let verdict = graded.verdict.expect("judged");
    let [residual, peak] = &verdict.criteria[..] else {
        panic!("{verdict:?}")
    };
    assert!(!residual.pass && residual.value.is_none(), "{residual:?}");
    let reason = residual.reason.as_ref().map(|r| r.to_string());
    let reason = reason.unwrap_or_default();
    assert!(
        reason.contains("your v1 (rad/s²) is not a finite number at "),
        "{reason}"
    );
    assert!(peak.pass, "{peak:?}");
}
