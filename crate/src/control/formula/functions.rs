//! The functions a formula may call: their names, arities and values.

/// A function a formula may call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Function {
    /// √x.
    Sqrt,
    /// eˣ.
    Exp,
    /// ln x.
    Ln,
    /// sin x.
    Sin,
    /// cos x.
    Cos,
    /// tanh x.
    Tanh,
    /// |x|.
    Abs,
    /// −1, 0 or 1.
    Sign,
    /// atan2(y, x).
    Atan2,
    /// min(a, b).
    Min,
    /// max(a, b).
    Max,
    /// sat(x, m) = x limited to [−m, m].
    Sat,
}

/// Every function: its name, its arguments and the id of its meaning in `core-law.ftl`
/// (`formula-function-` and the name: "sqrt(x): square root").
pub const FUNCTIONS: &[(&str, Function, usize, &str)] = &[
    ("sqrt", Function::Sqrt, 1, "formula-function-sqrt"),
    ("exp", Function::Exp, 1, "formula-function-exp"),
    ("ln", Function::Ln, 1, "formula-function-ln"),
    ("sin", Function::Sin, 1, "formula-function-sin"),
    ("cos", Function::Cos, 1, "formula-function-cos"),
    ("tanh", Function::Tanh, 1, "formula-function-tanh"),
    ("abs", Function::Abs, 1, "formula-function-abs"),
    ("sign", Function::Sign, 1, "formula-function-sign"),
    ("atan2", Function::Atan2, 2, "formula-function-atan2"),
    ("min", Function::Min, 2, "formula-function-min"),
    ("max", Function::Max, 2, "formula-function-max"),
    ("sat", Function::Sat, 2, "formula-function-sat"),
];

impl Function {
    pub(super) fn name(self) -> &'static str {
        FUNCTIONS.iter().find(|f| f.1 == self).expect("listed").0
    }

    pub(super) fn arity(self) -> usize {
        FUNCTIONS.iter().find(|f| f.1 == self).expect("listed").2
    }

    #[inline]
    pub(super) fn apply1(self, x: f64) -> f64 {
        match self {
            Function::Sqrt => x.sqrt(),
            Function::Exp => libm::exp(x),
            Function::Ln => libm::log(x),
            Function::Sin => libm::sin(x),
            Function::Cos => libm::cos(x),
            Function::Tanh => libm::tanh(x),
            Function::Abs => x.abs(),
            Function::Sign => {
                if x > 0.0 {
                    1.0
                } else if x < 0.0 {
                    -1.0
                } else {
                    x
                }
            }
            _ => unreachable!("two arguments"),
        }
    }

    #[inline]
    pub(super) fn apply2(self, a: f64, b: f64) -> f64 {
        match self {
            Function::Atan2 => libm::atan2(a, b),
            Function::Min => libm::fmin(a, b),
            Function::Max => libm::fmax(a, b),
            Function::Sat => libm::fmax(-b, libm::fmin(b, a)),
            _ => unreachable!("one argument"),
        }
    }
}
