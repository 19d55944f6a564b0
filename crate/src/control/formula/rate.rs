//! Forward mode: a program's time derivative from the signals and their rates.
//!
//! Each value on the stack carries its rate, and each operation applies its derivative rule
//! (the product rule, the quotient rule, the chain rule through a function). A signal whose rate
//! is not known is given the rate NaN, and the result is NaN whenever it depends on it.

use super::program::{Op, Program};
use super::{Function, MAX_DEPTH, SIGNALS};

/// The rate of f(x) for the function `f` of one argument, at x with rate dx: 0 when x does not
/// move (also where f has no finite slope, as √x and ln x at 0).
fn rate1(f: Function, x: f64, dx: f64) -> f64 {
    if dx == 0.0 {
        return 0.0;
    }
    match f {
        Function::Sqrt => dx / (2.0 * x.sqrt()),
        Function::Exp => libm::exp(x) * dx,
        Function::Ln => dx / x,
        Function::Sin => libm::cos(x) * dx,
        Function::Cos => -libm::sin(x) * dx,
        Function::Tanh => {
            let t = libm::tanh(x);
            (1.0 - t * t) * dx
        }
        Function::Abs => {
            if x == 0.0 {
                dx.abs()
            } else {
                x.signum() * dx
            }
        }
        // Piecewise constant: its rate is zero wherever it is defined.
        Function::Sign => 0.0,
        Function::Atan2 | Function::Min | Function::Max | Function::Sat => {
            unreachable!("two arguments")
        }
    }
}

/// The rate of f(a, b) for the function `f` of two arguments.
fn rate2(f: Function, (a, da): (f64, f64), (b, db): (f64, f64)) -> f64 {
    match f {
        Function::Atan2 => (b * da - a * db) / (a * a + b * b),
        Function::Min => {
            if a <= b {
                da
            } else {
                db
            }
        }
        Function::Max => {
            if a >= b {
                da
            } else {
                db
            }
        }
        // sat(a, m) = a inside [−m, m], ±m outside.
        Function::Sat => {
            if a > b {
                db
            } else if a < -b {
                -db
            } else {
                da
            }
        }
        Function::Sqrt
        | Function::Exp
        | Function::Ln
        | Function::Sin
        | Function::Cos
        | Function::Tanh
        | Function::Abs
        | Function::Sign => unreachable!("one argument"),
    }
}

/// The rate of aᵇ: b·aᵇ⁻¹·ȧ, plus aᵇ·ln a·ḃ when the exponent moves.
fn pow_rate((a, da): (f64, f64), (b, db): (f64, f64)) -> f64 {
    let base = if da == 0.0 {
        0.0
    } else {
        b * libm::pow(a, b - 1.0) * da
    };
    let exponent = if db == 0.0 {
        0.0
    } else {
        libm::pow(a, b) * libm::log(a) * db
    };
    base + exponent
}

impl Program {
    /// Its time derivative when the signals `s` change at the rates `r` (NaN for a rate not
    /// known); allocates nothing.
    pub fn eval_rate(&self, s: &[f64; SIGNALS], r: &[f64; SIGNALS]) -> f64 {
        const MASK: usize = MAX_DEPTH - 1;
        let mut stack = [(0.0f64, 0.0f64); MAX_DEPTH];
        let mut n = 0usize;
        let sig = |i: u16| (s[i as usize], r[i as usize]);
        let mul = |(a, da): (f64, f64), (b, db): (f64, f64)| (a * b, da * b + a * db);
        let div = |(a, da): (f64, f64), (b, db): (f64, f64)| (a / b, (da * b - a * db) / (b * b));
        for op in &self.ops {
            let top = n.wrapping_sub(1) & MASK;
            match *op {
                Op::Num(v) => {
                    stack[n & MASK] = (v, 0.0);
                    n += 1;
                }
                Op::Sig(i) => {
                    stack[n & MASK] = sig(i);
                    n += 1;
                }
                Op::SigMulSig(i, j) => {
                    stack[n & MASK] = mul(sig(i), sig(j));
                    n += 1;
                }
                Op::NumMulSig(v, j) => {
                    stack[n & MASK] = mul((v, 0.0), sig(j));
                    n += 1;
                }
                Op::Neg => stack[top] = (-stack[top].0, -stack[top].1),
                Op::Add | Op::Sub | Op::Mul | Op::Div | Op::Pow | Op::Call2(_) => {
                    let (a, b) = (stack[n.wrapping_sub(2) & MASK], stack[top]);
                    n -= 1;
                    stack[n.wrapping_sub(1) & MASK] = match *op {
                        Op::Add => (a.0 + b.0, a.1 + b.1),
                        Op::Sub => (a.0 - b.0, a.1 - b.1),
                        Op::Mul => mul(a, b),
                        Op::Div => div(a, b),
                        Op::Pow => (libm::pow(a.0, b.0), pow_rate(a, b)),
                        Op::Call2(f) => (f.apply2(a.0, b.0), rate2(f, a, b)),
                        _ => unreachable!("a binary operation"),
                    };
                }
                Op::AddSig(i) => {
                    let b = sig(i);
                    stack[top] = (stack[top].0 + b.0, stack[top].1 + b.1);
                }
                Op::SubSig(i) => {
                    let b = sig(i);
                    stack[top] = (stack[top].0 - b.0, stack[top].1 - b.1);
                }
                Op::MulSig(i) => stack[top] = mul(stack[top], sig(i)),
                Op::DivSig(i) => stack[top] = div(stack[top], sig(i)),
                Op::AddNum(v) => stack[top].0 += v,
                Op::SubNum(v) => stack[top].0 -= v,
                Op::MulNum(v) => stack[top] = mul(stack[top], (v, 0.0)),
                Op::DivNum(v) => stack[top] = div(stack[top], (v, 0.0)),
                Op::Call1(f) => {
                    let (x, dx) = stack[top];
                    stack[top] = (f.apply1(x), rate1(f, x, dx));
                }
            }
        }
        stack[0].1
    }
}

#[cfg(test)]
mod tests {
    use crate::control::formula::{index, Program, SIGNALS};

    /// The rate of `text` when a1, a3 and z1 take the values and rates given, against a central
    /// difference.
    fn check(text: &str) {
        let program = Program::parse(text, 4).unwrap();
        let (mut s, mut r) = ([0.0; SIGNALS], [0.0; SIGNALS]);
        for (name, v, dv) in [("a1", 0.7, 0.3), ("a3", 1.3, -0.4), ("z1", -0.6, 0.9)] {
            s[index(name).unwrap()] = v;
            r[index(name).unwrap()] = dv;
        }
        let at = |h: f64| {
            let mut t = s;
            for i in 0..SIGNALS {
                t[i] += h * r[i];
            }
            program.eval(&t)
        };
        let h = 1e-6;
        let numeric = (at(h) - at(-h)) / (2.0 * h);
        let exact = program.eval_rate(&s, &r);
        assert!(
            (exact - numeric).abs() <= 1e-6 * numeric.abs().max(1.0),
            "{text}: {exact} against {numeric}"
        );
    }

    #[test]
    fn every_operation_and_function_follows_its_derivative_rule() {
        for text in [
            "a1*a3 - 2*z1 + 3 - a1/a3 + a1*(a3 + z1) - z1/2 + 4*a1 - (a1 - 5)",
            "a1^2 + a3^a1 + 2^z1 + a1^3.5",
            "sqrt(a1) + exp(z1) + ln(a3) + sin(a1*z1) + cos(a3) + tanh(z1)",
            "abs(z1) + sign(z1)*a1 + atan2(a1, z1) + min(a1, a3) + max(a1, a3)",
            "sat(z1, a1) + sat(a3, a1) + sat(-a3, a1)",
            "-(a1*z1)/(a3 - z1) + z1*z1*z1",
        ] {
            check(text);
        }
    }

    #[test]
    fn a_rate_not_known_reaches_the_result() {
        let program = Program::parse("a1*x2 + z1", 4).unwrap();
        let mut r = [0.0; SIGNALS];
        r[index("x2").unwrap()] = f64::NAN;
        assert!(program.eval_rate(&[1.0; SIGNALS], &r).is_nan());
        let program = Program::parse("a1*z1", 4).unwrap();
        assert_eq!(program.eval_rate(&[1.0; SIGNALS], &r), 0.0);
    }
}
