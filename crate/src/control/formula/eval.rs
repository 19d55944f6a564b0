//! Evaluation: a program's value from the signals, each sample, without allocating.

use super::program::{Op, Program};
use super::{MAX_DEPTH, SIGNALS};

impl Program {
    /// Its value with the signals `s` (indexed as [`NAMES`](super::NAMES)); allocates nothing.
    #[inline]
    pub fn eval(&self, s: &[f64; SIGNALS]) -> f64 {
        // A program needs at most MAX_DEPTH (a power of two) values: the mask keeps every index
        // in the stack without a bounds check, and never changes one.
        const MASK: usize = MAX_DEPTH - 1;
        let mut stack = [0.0f64; MAX_DEPTH];
        let mut n = 0usize;
        let signal = |i: u16| s[i as usize];
        for op in &self.ops {
            // The value on top, which every operation but a push works on.
            let top = (n.wrapping_sub(1)) & MASK;
            match *op {
                Op::Num(v) => {
                    stack[n & MASK] = v;
                    n += 1;
                }
                Op::Sig(i) => {
                    stack[n & MASK] = signal(i);
                    n += 1;
                }
                Op::SigMulSig(i, j) => {
                    stack[n & MASK] = signal(i) * signal(j);
                    n += 1;
                }
                Op::NumMulSig(v, j) => {
                    stack[n & MASK] = v * signal(j);
                    n += 1;
                }
                Op::Neg => stack[top] = -stack[top],
                Op::Add | Op::Sub | Op::Mul | Op::Div | Op::Pow | Op::Call2(_) => {
                    let (a, b) = (stack[(n.wrapping_sub(2)) & MASK], stack[top]);
                    n -= 1;
                    stack[n.wrapping_sub(1) & MASK] = match *op {
                        Op::Add => a + b,
                        Op::Sub => a - b,
                        Op::Mul => a * b,
                        Op::Div => a / b,
                        Op::Pow => libm::pow(a, b),
                        Op::Call2(f) => f.apply2(a, b),
                        _ => unreachable!("a binary operation"),
                    };
                }
                Op::AddSig(i) => stack[top] += signal(i),
                Op::SubSig(i) => stack[top] -= signal(i),
                Op::MulSig(i) => stack[top] *= signal(i),
                Op::DivSig(i) => stack[top] /= signal(i),
                Op::AddNum(v) => stack[top] += v,
                Op::SubNum(v) => stack[top] -= v,
                Op::MulNum(v) => stack[top] *= v,
                Op::DivNum(v) => stack[top] /= v,
                Op::Call1(f) => stack[top] = f.apply1(stack[top]),
            }
        }
        debug_assert!(n == 1 && self.depth <= MAX_DEPTH);
        stack[0]
    }
}

#[cfg(test)]
mod tests {
    use crate::control::formula::{index, Program, SIGNALS};

    fn signals(values: &[(&str, f64)]) -> [f64; SIGNALS] {
        let mut s = [0.0; SIGNALS];
        for (n, v) in values {
            s[index(n).unwrap()] = *v;
        }
        s
    }

    fn value(text: &str, s: &[(&str, f64)]) -> f64 {
        Program::parse(text, 4).unwrap().eval(&signals(s))
    }

    #[test]
    fn precedence_and_grouping_follow_the_usual_rules() {
        assert_eq!(value("1 + 2*3", &[]), 7.0);
        assert_eq!(value("-2^2", &[]), -4.0);
        assert_eq!(value("2^3^2", &[]), 512.0);
        assert_eq!(value("2^-1", &[]), 0.5);
        assert_eq!(value("8/4/2", &[]), 1.0);
        assert_eq!(value("1 - 2 - 3", &[]), -4.0);
        assert_eq!(value("-k1s1*z1", &[("k1s1", 3.0), ("z1", 2.0)]), -6.0);
        assert_eq!(value("2·3 − 1", &[]), 5.0);
        assert_eq!(value("1.5e3 + .5", &[]), 1500.5);
        assert_eq!(value("sat(5, 2) + sat(-5, 2) + sat(1, 2)", &[]), 1.0);
        assert_eq!(value("max(1, 2) - min(1, 2)", &[]), 1.0);
        assert_eq!(value("sign(-3) + abs(-3) + sqrt(4)", &[]), 4.0);
        assert!((value("atan2(1, 1)", &[]) - std::f64::consts::FRAC_PI_4).abs() < 1e-15);
    }

    #[test]
    fn a_product_is_evaluated_in_the_order_written() {
        // (a·b)·c and a·(b·c) can differ in the last bit: the program keeps the order written.
        let s = [("a1", 0.1), ("a3", 0.7), ("k1", 0.3)];
        assert_eq!(value("a1*a3*k1", &s), (0.1 * 0.7) * 0.3);
        assert_eq!(value("a1*(a3*k1)", &s), 0.1 * (0.7 * 0.3));
    }
}
