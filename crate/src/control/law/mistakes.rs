//! Mistakes students make in each step, named by the verdict when a law equals one.

use super::PAPER;
use crate::control::formula::Program;

/// One mistake: the paper's law with each [what the paper has, what the student writes] changed,
/// and what is wrong.
type Mistake = (&'static [(&'static str, &'static str)], &'static str);

/// Mistakes a student makes in each step: the verdict names the one a law equals. A single term
/// or part of a term missing, with the wrong sign or scaled is found without a list (see
/// [`check`](super::check)).
const MISTAKES: [&[Mistake]; 4] = [
    &[
        (&[("k1s1*z1", "k1*z1")], "it has k1 where (28) has k1s1 = k1 − a3"),
        (&[("a3*wd", "a3*x1h")], "it has a3·x̂1 where (27) has a3·ω_d"),
    ],
    &[
        (
            &[("(-k2s1*z2", "(-k2*z2")],
            "it has k2 where (36) has k2s1 = k2 − a7 − a8: the −(a7 + a8)·z2 of ż2 is then left in",
        ),
        (
            &[("a3*dwd + da2", "a3*wd + a2")],
            "it takes v̇1 as printed in (31), with both of its typos: a3·ω_d where the derivative of a3·ω_d is a3·ω̇_d, and â2 where the derivative of â2 is its rate (0 for a known load)",
        ),
        (
            &[("a3*dwd", "a3*wd")],
            "it takes v̇1 as printed in (31), with a3·ω_d where the derivative of a3·ω_d is a3·ω̇_d",
        ),
        (
            &[("+ da2", "+ a2")],
            "it takes v̇1 as printed in (31), with â2 where the derivative of â2 is its rate (0 for a known load)",
        ),
        (
            &[("-robust*h2", "-h2")],
            "it writes the robust term −h2²/(4·ε2)·z2 of (38) without the switch robust, so it acts while the robust terms are off",
        ),
    ],
    &[
        (
            &[("- k3*z3", "- k3*(x4h*x4h + x5h*x5h - psi_d*psi_d)")],
            "it takes ψ_d as the flux modulus (ψ_d²) where the paper's z3 = x̂4² + x̂5² − ψ_d takes it as the squared modulus",
        ),
        (
            &[(
                "-(-2*a8*(x4h*x4h + x5h*x5h) - 2*a10*(xt2*x4h + xt3*x5h) + 2*(x4h*si4 + x5h*si5))",
                "-(-a8*(x4h*x4h + x5h*x5h) - a10*(xt2*x4h + xt3*x5h) + (x4h*si4 + x5h*si5))",
            )],
            "it drops the factor 2 throughout ψ3: the rate of x̂4² + x̂5² is 2·(x̂4·x̂̇4 + x̂5·x̂̇5)",
        ),
    ],
    &[
        (
            &[(
                "+ 2*(l41*x4h + l51*x5h)*dxt2 + 2*(l42*x4h + l52*x5h)*dxt3 ",
                "",
            )],
            "it leaves out the residuals' chain-rule terms 2·(l41·x̂4 + l51·x̂5)·ẋ̃2 and 2·(l42·x̂4 + l52·x̂5)·ẋ̃3 of ψ4",
        ),
        (
            &[
                ("*dx4h", "*(-a8*x4h - a9*x1h*x5h + a10*x2h)"),
                ("*dx5h", "*(-a8*x5h + a9*x1h*x4h + a10*x3h)"),
            ],
            "it has the model's drifts f̂4, f̂5 where ψ4 has the observer's rates x̂̇4 = f̂4 + si4 and x̂̇5 = f̂5 + si5: the injections are left out",
        ),
        (
            &[("*dx4h", "*(-a8*x4h - a9*x1h*x5h + a10*x2h)")],
            "it has the model's drift f̂4 where ψ4 has the observer's rate x̂̇4 = f̂4 + si4: the injection si4 is left out",
        ),
        (
            &[("*dx5h", "*(-a8*x5h + a9*x1h*x4h + a10*x3h)")],
            "it has the model's drift f̂5 where ψ4 has the observer's rate x̂̇5 = f̂5 + si5: the injection si5 is left out",
        ),
        (
            &[("2*(si4 + a10*x2h", "2*(a10*x2h")],
            "the factor of x̂̇4 leaves out si4: the rate of 2·x̂4·si4 in ψ3 gives 2·si4·x̂̇4",
        ),
        (
            &[("2*(si5 + a10*x3h", "2*(a10*x3h")],
            "the factor of x̂̇5 leaves out si5: the rate of 2·x̂5·si5 in ψ3 gives 2·si5·x̂̇5",
        ),
        (
            &[("-robust*h4", "-h4")],
            "it writes the robust term −h4²/(4·ε4)·z4 of (53) without the switch robust, so it acts while the robust terms are off",
        ),
    ],
];

/// The catalogued mistakes of step `step` as laws, each with what it gets wrong.
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
