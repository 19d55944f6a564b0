//! Mistakes students make in each step, named by the verdict when a law equals one.

use super::PAPER;
use crate::control::formula::Program;

/// One mistake: the paper's law with each [what the paper has, what the student writes] changed,
/// and what is wrong (the id of its message in `core-law.ftl`).
type Mistake = (&'static [(&'static str, &'static str)], &'static str);

/// Mistakes a student makes in each step: the verdict names the one a law equals. A single term
/// or part of a term missing, with the wrong sign or scaled is found without a list (see
/// [`check`](super::check)).
const MISTAKES: [&[Mistake]; 4] = [
    &[
        (&[("k1s1*z1", "k1*z1")], "law-mistake-k1"),
        (&[("a3*wd", "a3*x1h")], "law-mistake-a3-x1h"),
    ],
    &[
        (&[("(-k2s1*z2", "(-k2*z2")], "law-mistake-k2"),
        (&[("a3*dwd + da2", "a3*wd + a2")], "law-mistake-printed-dv1"),
        (&[("a3*dwd", "a3*wd")], "law-mistake-printed-dv1-wd"),
        (&[("+ da2", "+ a2")], "law-mistake-printed-dv1-a2"),
        (&[("-robust*h2", "-h2")], "law-mistake-robust-2"),
    ],
    &[
        (
            &[("- k3*z3", "- k3*(x4h*x4h + x5h*x5h - psi_d*psi_d)")],
            "law-mistake-psi-modulus",
        ),
        (
            &[(
                "-(-2*a8*(x4h*x4h + x5h*x5h) - 2*a10*(xt2*x4h + xt3*x5h) + 2*(x4h*si4 + x5h*si5))",
                "-(-a8*(x4h*x4h + x5h*x5h) - a10*(xt2*x4h + xt3*x5h) + (x4h*si4 + x5h*si5))",
            )],
            "law-mistake-factor-2",
        ),
    ],
    &[
        (
            &[(
                "+ 2*(l41*x4h + l51*x5h)*dxt2 + 2*(l42*x4h + l52*x5h)*dxt3 ",
                "",
            )],
            "law-mistake-residual-rates",
        ),
        (
            &[
                ("*dx4h", "*(-a8*x4h - a9*x1h*x5h + a10*x2h)"),
                ("*dx5h", "*(-a8*x5h + a9*x1h*x4h + a10*x3h)"),
            ],
            "law-mistake-drifts",
        ),
        (
            &[("*dx4h", "*(-a8*x4h - a9*x1h*x5h + a10*x2h)")],
            "law-mistake-drift-4",
        ),
        (
            &[("*dx5h", "*(-a8*x5h + a9*x1h*x4h + a10*x3h)")],
            "law-mistake-drift-5",
        ),
        (
            &[("2*(si4 + a10*x2h", "2*(a10*x2h")],
            "law-mistake-factor-si4",
        ),
        (
            &[("2*(si5 + a10*x3h", "2*(a10*x3h")],
            "law-mistake-factor-si5",
        ),
        (&[("-robust*h4", "-h4")], "law-mistake-robust-4"),
    ],
];

/// The catalogued mistakes of step `step` as laws, each with the id of the message that says what
/// it gets wrong.
pub(super) fn mistakes(step: u8) -> Vec<(Program, &'static str)> {
    let paper = PAPER[step as usize - 1];
    MISTAKES[step as usize - 1]
        .iter()
        .map(|(changes, why)| {
            let mut text = paper.to_string();
            for (has, writes) in *changes {
                assert_eq!(text.matches(has).count(), 1, "{has} stands once in the law");
                text = text.replacen(has, writes, 1);
            }
            (
                Program::parse(&text, step).expect("a listed mistake parses"),
                *why,
            )
        })
        .collect()
}
