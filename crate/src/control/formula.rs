//! The control-law language: a formula of the controller's signals, parsed once into a compact
//! program that is evaluated each sample without allocating.
//!
//! A formula uses numbers, the names in [`NAMES`], + − · / ^ (`*` or `·` for the product, `-` or
//! `−` for the minus), parentheses and the functions of [`FUNCTIONS`]. The unary minus binds
//! tighter than the product and looser than the power: `-k1s1*z1` is (−k1s1)·z1, `-x^2` is −(x²);
//! `^` groups to the right. Every function is the `libm` crate's (or IEEE-exact), so a formula
//! gives the same bits natively and in WebAssembly.

use std::fmt;

/// Longest formula accepted (characters): the paper's v4 written out takes 283.
pub const MAX_CHARS: usize = 2000;
/// Most operations a program may have: about two per name or number (the paper's v4 has 61).
pub const MAX_OPS: usize = 400;
/// Deepest stack a program may need; the evaluator's stack holds this many values.
pub const MAX_DEPTH: usize = 32;
/// Deepest nesting of parentheses, signs and powers the parser follows.
pub const MAX_NESTING: usize = 64;

/// A named signal a formula may use: its name, its symbol in TeX, its unit and its meaning, and
/// the first step whose formula may use it (the later steps' errors and virtual controls follow
/// from the earlier steps' laws).
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Name {
    /// The name in a formula.
    pub name: &'static str,
    /// Its symbol, in TeX.
    pub tex: &'static str,
    /// Its unit.
    pub unit: &'static str,
    /// Its meaning.
    pub doc: &'static str,
    /// The first step (1–4) whose law may use it.
    pub from_step: u8,
}

const fn name(
    name: &'static str,
    tex: &'static str,
    unit: &'static str,
    doc: &'static str,
    from_step: u8,
) -> Name {
    Name {
        name,
        tex,
        unit,
        doc,
        from_step,
    }
}

/// Every name a formula may use, in the order of the signal vector the controller fills.
#[rustfmt::skip]
pub const NAMES: &[Name] = &[
    name("x1h", r"\hat{x}_1", "rad/s", "estimated rotor speed ω̂ (posterior x̂1)", 1),
    name("x2h", r"\hat{x}_2", "A", "estimated stator current î_sa", 1),
    name("x3h", r"\hat{x}_3", "A", "estimated stator current î_sb", 1),
    name("x4h", r"\hat{x}_4", "Wb", "estimated rotor flux φ̂_ra", 1),
    name("x5h", r"\hat{x}_5", "Wb", "estimated rotor flux φ̂_rb", 1),
    name("x2", "x_2", "A", "measured stator current i_sa", 1),
    name("x3", "x_3", "A", "measured stator current i_sb", 1),
    name("xt2", r"\tilde{x}_2", "A", "residual x̃2 = x2 − x̂2", 1),
    name("xt3", r"\tilde{x}_3", "A", "residual x̃3 = x3 − x̂3", 1),
    name("dxt2", r"\dot{\tilde{x}}_2", "A/s", "nominal rate of x̃2: −(a7 + l21)·x̃2 − l22·x̃3", 1),
    name("dxt3", r"\dot{\tilde{x}}_3", "A/s", "nominal rate of x̃3: −l31·x̃2 − (a7 + l32)·x̃3", 1),
    name("dx4h", r"\dot{\hat{x}}_4", "Wb/s", "observer rate of x̂4: −a8·x̂4 − a9·x̂1·x̂5 + a10·x̂2 + si4", 1),
    name("dx5h", r"\dot{\hat{x}}_5", "Wb/s", "observer rate of x̂5: −a8·x̂5 + a9·x̂1·x̂4 + a10·x̂3 + si5", 1),
    name("wd", r"\omega_d", "rad/s", "speed reference ω_d", 1),
    name("dwd", r"\dot{\omega}_d", "rad/s²", "its first derivative", 1),
    name("ddwd", r"\ddot{\omega}_d", "rad/s³", "its second derivative", 1),
    name("psi_d", r"\psi_d", "Wb²", "flux target for x̂4² + x̂5²", 1),
    name("si1", r"\mathit{si}_1", "rad/s²", "observer injection into x̂1: l11·x̃2 + l12·x̃3", 1),
    name("si2", r"\mathit{si}_2", "A/s", "observer injection into x̂2", 1),
    name("si3", r"\mathit{si}_3", "A/s", "observer injection into x̂3", 1),
    name("si4", r"\mathit{si}_4", "Wb/s", "observer injection into x̂4", 1),
    name("si5", r"\mathit{si}_5", "Wb/s", "observer injection into x̂5", 1),
    name("l11", "l_{11}", "rad/(A s²)", "observer gain L = K/Ts, row 1, column 1", 1),
    name("l12", "l_{12}", "rad/(A s²)", "observer gain, row 1, column 2", 1),
    name("l21", "l_{21}", "1/s", "observer gain, row 2, column 1", 1),
    name("l22", "l_{22}", "1/s", "observer gain, row 2, column 2", 1),
    name("l31", "l_{31}", "1/s", "observer gain, row 3, column 1", 1),
    name("l32", "l_{32}", "1/s", "observer gain, row 3, column 2", 1),
    name("l41", "l_{41}", "Wb/(A s)", "observer gain, row 4, column 1", 1),
    name("l42", "l_{42}", "Wb/(A s)", "observer gain, row 4, column 2", 1),
    name("l51", "l_{51}", "Wb/(A s)", "observer gain, row 5, column 1", 1),
    name("l52", "l_{52}", "Wb/(A s)", "observer gain, row 5, column 2", 1),
    name("a1", "a_1", "1/(kg m²)", "μ = 3·np·M/(2·J·Lr): a1·(x3·x̂4 − x2·x̂5) is the torque over J", 1),
    name("a2", "a_2", "rad/s²", "T0/J (the estimate â2 when the EKF estimates the load)", 1),
    name("a3", "a_3", "1/s", "Cf/J", 1),
    name("a5", "a_5", "1/(H s)", "α·β, with α = Rr/Lr and β = M/(σ·Lr)", 1),
    name("a6", "a_6", "1/H", "np·β", 1),
    name("a7", "a_7", "1/s", "γ = Rs/σ + α·β·M", 1),
    name("a8", "a_8", "1/s", "α = Rr/Lr", 1),
    name("a9", "a_9", "", "np", 1),
    name("a10", "a_{10}", "Ω", "α·M", 1),
    name("b", "b", "1/H", "1/σ", 1),
    name("da2", r"\dot{\hat{a}}_2", "rad/s³", "rate of â2 (its injection) when the EKF estimates the load, else 0", 1),
    name("k1", "k_1", "1/s", "speed-error rate", 1),
    name("k2", "k_2", "1/s", "torque-error rate (k2 = a7 + a8 + k2s1)", 1),
    name("k3", "k_3", "1/s", "flux-error rate", 1),
    name("k4", "k_4", "1/s", "flux-rate-error rate", 1),
    name("k1s1", "k_{1s1}", "1/s", "k1 − a3", 1),
    name("k2s1", "k_{2s1}", "1/s", "k2 − a7 − a8", 1),
    name("h2", "h_2", "rad/s³", "bound on |d̃2| of (38)", 1),
    name("eps2", r"\varepsilon_2", "rad²/s⁵", "ε2 of (38)", 1),
    name("h4", "h_4", "Wb²/s²", "bound on |d̃4| of (53)", 1),
    name("eps4", r"\varepsilon_4", "Wb⁴/s³", "ε4 of (53)", 1),
    name("robust", r"\rho", "", "1 when the robust terms (38) and (53) are on, else 0", 1),
    name("z1", "z_1", "rad/s", "speed error x̂1 − ω_d", 1),
    name("z3", "z_3", "Wb²", "flux error x̂4² + x̂5² − ψ_d", 1),
    name("v1", "v_1", "rad/s²", "step 1's virtual control (yours when you wrote it)", 2),
    name("z2", "z_2", "rad/s²", "torque error a1·(x3·x̂4 − x2·x̂5) − v1", 2),
    name("v3", "v_3", "Wb²/s", "step 3's virtual control (yours when you wrote it)", 4),
    name("z4", "z_4", "Wb²/s", "flux-rate error 2·a10·(x2·x̂4 + x3·x̂5) − v3", 4),
];

/// The number of signals the controller fills.
pub const SIGNALS: usize = NAMES.len();

/// The index of `name` in [`NAMES`].
pub fn index(name: &str) -> Option<usize> {
    NAMES.iter().position(|n| n.name == name)
}

/// The index of `name` in [`NAMES`], when compiled (a name that is not there fails the build).
pub const fn at(name: &str) -> usize {
    let mut i = 0;
    while i < NAMES.len() {
        let (a, b) = (NAMES[i].name.as_bytes(), name.as_bytes());
        if a.len() == b.len() {
            let mut j = 0;
            while j < a.len() && a[j] == b[j] {
                j += 1;
            }
            if j == a.len() {
                return i;
            }
        }
        i += 1;
    }
    panic!("not a signal name")
}

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

/// Every function: its name, its arguments and its meaning.
pub const FUNCTIONS: &[(&str, Function, usize, &str)] = &[
    ("sqrt", Function::Sqrt, 1, "sqrt(x): square root"),
    ("exp", Function::Exp, 1, "exp(x): exponential"),
    ("ln", Function::Ln, 1, "ln(x): natural logarithm"),
    ("sin", Function::Sin, 1, "sin(x): sine, x in rad"),
    ("cos", Function::Cos, 1, "cos(x): cosine, x in rad"),
    ("tanh", Function::Tanh, 1, "tanh(x): hyperbolic tangent"),
    ("abs", Function::Abs, 1, "abs(x): absolute value"),
    ("sign", Function::Sign, 1, "sign(x): −1, 0 or 1"),
    (
        "atan2",
        Function::Atan2,
        2,
        "atan2(y, x), the angle of (x, y) (rad)",
    ),
    ("min", Function::Min, 2, "min(a, b): the smaller"),
    ("max", Function::Max, 2, "max(a, b): the larger"),
    ("sat", Function::Sat, 2, "sat(x, m): x limited to [−m, m]"),
];

impl Function {
    fn name(self) -> &'static str {
        FUNCTIONS.iter().find(|f| f.1 == self).expect("listed").0
    }

    fn arity(self) -> usize {
        FUNCTIONS.iter().find(|f| f.1 == self).expect("listed").2
    }

    #[inline]
    fn apply1(self, x: f64) -> f64 {
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
    fn apply2(self, a: f64, b: f64) -> f64 {
        match self {
            Function::Atan2 => libm::atan2(a, b),
            Function::Min => libm::fmin(a, b),
            Function::Max => libm::fmax(a, b),
            Function::Sat => libm::fmax(-b, libm::fmin(b, a)),
            _ => unreachable!("one argument"),
        }
    }
}

/// Why a formula was refused: where (the character, counted from 1) and why.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct FormulaError {
    /// The first character the problem concerns, counted from 1 (0: the formula as a whole).
    pub at: usize,
    /// How many characters it spans (at least 1 when `at` > 0).
    pub len: usize,
    /// The reason.
    pub reason: String,
}

impl FormulaError {
    fn new(at: usize, len: usize, reason: impl Into<String>) -> FormulaError {
        FormulaError {
            at,
            len: len.max(1),
            reason: reason.into(),
        }
    }
}

impl fmt::Display for FormulaError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.at == 0 {
            write!(f, "{}", self.reason)
        } else {
            write!(f, "at character {}: {}", self.at, self.reason)
        }
    }
}

impl std::error::Error for FormulaError {}

/// A binary operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    /// a + b.
    Add,
    /// a − b.
    Sub,
    /// a · b.
    Mul,
    /// a / b.
    Div,
    /// a ^ b.
    Pow,
}

/// A parsed formula's tree: what the TeX, the terms and the program are made from.
#[derive(Clone, Debug, PartialEq)]
pub enum Node {
    /// A number, with the text it was written as.
    Num(f64, String),
    /// A signal, by its index in [`NAMES`].
    Sig(usize),
    /// −x.
    Neg(Box<Node>),
    /// x op y.
    Bin(BinOp, Box<Node>, Box<Node>),
    /// f(args).
    Call(Function, Vec<Node>),
    /// (x), kept so that the TeX shows the student's parentheses.
    Paren(Box<Node>),
}

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Num(f64, String),
    Ident(String),
    Op(char),
}

/// The tokens of `text`, each with its first character (from 1) and its length in characters.
fn tokens(text: &str) -> Result<Vec<(Token, usize, usize)>, FormulaError> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        let start = i;
        if c.is_whitespace() {
            i += 1;
            continue;
        }
        if c.is_ascii_digit() || (c == '.' && chars.get(i + 1).is_some_and(char::is_ascii_digit)) {
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            if i < chars.len() && (chars[i] == 'e' || chars[i] == 'E') {
                let mut j = i + 1;
                if j < chars.len() && (chars[j] == '+' || chars[j] == '-') {
                    j += 1;
                }
                if j < chars.len() && chars[j].is_ascii_digit() {
                    i = j;
                    while i < chars.len() && chars[i].is_ascii_digit() {
                        i += 1;
                    }
                }
            }
            let written: String = chars[start..i].iter().collect();
            let value: f64 = written.parse().map_err(|_| {
                FormulaError::new(start + 1, i - start, format!("'{written}' is not a number"))
            })?;
            if !value.is_finite() {
                return Err(FormulaError::new(
                    start + 1,
                    i - start,
                    format!("'{written}' is too large for a number"),
                ));
            }
            out.push((Token::Num(value, written), start + 1, i - start));
            continue;
        }
        if c.is_ascii_alphabetic() || c == '_' {
            while i < chars.len() && (chars[i].is_ascii_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push((
                Token::Ident(chars[start..i].iter().collect()),
                start + 1,
                i - start,
            ));
            continue;
        }
        let op = match c {
            '+' | '-' | '*' | '/' | '^' | '(' | ')' | ',' => c,
            '−' => '-',
            '·' | '×' => '*',
            _ => {
                return Err(FormulaError::new(
                    start + 1,
                    1,
                    format!(
                    "'{c}' is not part of the language (+ − * / ^, parentheses, names, numbers)"
                ),
                ))
            }
        };
        out.push((Token::Op(op), start + 1, 1));
        i += 1;
    }
    Ok(out)
}

/// The parser: precedence climbing over the tokens, refusing names the step may not use.
struct Parser<'a> {
    tokens: &'a [(Token, usize, usize)],
    pos: usize,
    /// Where the formula ends (one past its last character), for errors at its end.
    end: usize,
    step: u8,
    /// How deep in parentheses, signs and powers the parser is.
    nesting: usize,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&(Token, usize, usize)> {
        self.tokens.get(self.pos)
    }

    fn at_op(&self, op: char) -> bool {
        matches!(self.peek(), Some((Token::Op(c), _, _)) if *c == op)
    }

    fn here(&self) -> (usize, usize) {
        self.peek().map_or((self.end, 1), |t| (t.1, t.2))
    }

    fn expr(&mut self) -> Result<Node, FormulaError> {
        let mut left = self.term()?;
        while self.at_op('+') || self.at_op('-') {
            let op = if self.at_op('+') {
                BinOp::Add
            } else {
                BinOp::Sub
            };
            self.pos += 1;
            let right = self.term()?;
            left = Node::Bin(op, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    fn term(&mut self) -> Result<Node, FormulaError> {
        let mut left = self.unary()?;
        while self.at_op('*') || self.at_op('/') {
            let op = if self.at_op('*') {
                BinOp::Mul
            } else {
                BinOp::Div
            };
            let (at, _) = self.here();
            self.pos += 1;
            let right = self.unary()?;
            if op == BinOp::Div && constant(&right) == Some(0.0) {
                return Err(FormulaError::new(at, 1, "division by zero"));
            }
            left = Node::Bin(op, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    fn unary(&mut self) -> Result<Node, FormulaError> {
        self.nesting += 1;
        let node = self.unary_inner();
        self.nesting -= 1;
        node
    }

    fn unary_inner(&mut self) -> Result<Node, FormulaError> {
        if self.nesting > MAX_NESTING {
            let (at, len) = self.here();
            return Err(FormulaError::new(
                at,
                len,
                format!("the formula nests deeper than {MAX_NESTING} levels here"),
            ));
        }
        if self.at_op('-') {
            self.pos += 1;
            return Ok(Node::Neg(Box::new(self.unary()?)));
        }
        if self.at_op('+') {
            self.pos += 1;
            return self.unary();
        }
        self.power()
    }

    fn power(&mut self) -> Result<Node, FormulaError> {
        let base = self.primary()?;
        if self.at_op('^') {
            self.pos += 1;
            let exponent = self.unary()?;
            return Ok(Node::Bin(BinOp::Pow, Box::new(base), Box::new(exponent)));
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<Node, FormulaError> {
        let Some((token, at, len)) = self.peek().cloned() else {
            return Err(FormulaError::new(
                self.end,
                1,
                "the formula ends where a number, a name or '(' is expected",
            ));
        };
        self.pos += 1;
        match token {
            Token::Num(v, written) => Ok(Node::Num(v, written)),
            Token::Op('(') => {
                let inner = self.expr()?;
                if !self.at_op(')') {
                    let (here, n) = self.here();
                    return Err(if self.peek().is_none() {
                        FormulaError::new(at, 1, "this '(' is never closed")
                    } else {
                        FormulaError::new(here, n, "expected ')' or an operator here")
                    });
                }
                self.pos += 1;
                Ok(Node::Paren(Box::new(inner)))
            }
            Token::Ident(id) if self.at_op('(') => self.call(&id, at, len),
            Token::Ident(id) => self.signal(&id, at, len),
            Token::Op(c) => Err(FormulaError::new(
                at,
                1,
                format!("'{c}' where a number, a name or '(' is expected"),
            )),
        }
    }

    fn call(&mut self, id: &str, at: usize, len: usize) -> Result<Node, FormulaError> {
        let Some(&(_, f, arity, _)) = FUNCTIONS.iter().find(|f| f.0 == id) else {
            let known: Vec<&str> = FUNCTIONS.iter().map(|f| f.0).collect();
            return Err(FormulaError::new(
                at,
                len,
                format!("no function '{id}': the functions are {}", known.join(", ")),
            ));
        };
        self.pos += 1; // '('
        let mut args = vec![self.expr()?];
        while self.at_op(',') {
            self.pos += 1;
            args.push(self.expr()?);
        }
        if !self.at_op(')') {
            let (here, n) = self.here();
            return Err(FormulaError::new(
                here,
                n,
                format!("expected ',' or ')' in {id}( )"),
            ));
        }
        self.pos += 1;
        if args.len() != arity {
            return Err(FormulaError::new(
                at,
                len,
                format!(
                    "{id} takes {arity} argument{}, not {}",
                    if arity == 1 { "" } else { "s" },
                    args.len()
                ),
            ));
        }
        Ok(Node::Call(f, args))
    }

    fn signal(&mut self, id: &str, at: usize, len: usize) -> Result<Node, FormulaError> {
        match index(id) {
            Some(i) if NAMES[i].from_step <= self.step => Ok(Node::Sig(i)),
            Some(i) => Err(FormulaError::new(
                at,
                len,
                format!(
                    "'{id}' is not known in step {}: it comes from step {}'s law",
                    self.step,
                    NAMES[i].from_step - 1
                ),
            )),
            None if FUNCTIONS.iter().any(|f| f.0 == id) => Err(FormulaError::new(
                at,
                len,
                format!("'{id}' is a function: write {id}( )"),
            )),
            None => Err(FormulaError::new(
                at,
                len,
                format!("unknown name '{id}' (see the list of names)"),
            )),
        }
    }
}

/// The value of `node` when it holds no signal.
fn constant(node: &Node) -> Option<f64> {
    let mut ops = Vec::new();
    compile(node, &mut ops);
    let program = Program {
        ops,
        depth: MAX_DEPTH,
    };
    let none = [0.0; SIGNALS];
    (!program.ops.iter().any(|op| op.names_signal())).then(|| program.eval(&none))
}

/// Parses `text` as the law of step `step` (1–4).
pub fn parse(text: &str, step: u8) -> Result<Node, FormulaError> {
    let length = text.chars().count();
    if length > MAX_CHARS {
        return Err(FormulaError::new(
            0,
            0,
            format!("the formula has {length} characters, more than the {MAX_CHARS} allowed"),
        ));
    }
    let tokens = tokens(text)?;
    if tokens.is_empty() {
        return Err(FormulaError::new(0, 0, "the formula is empty"));
    }
    let mut parser = Parser {
        tokens: &tokens,
        pos: 0,
        end: length + 1,
        step,
        nesting: 0,
    };
    let node = parser.expr()?;
    if let Some((token, at, len)) = parser.peek() {
        let what = match token {
            Token::Op(')') => "this ')' has no '(' before it".to_string(),
            _ => "expected an operator here (a product is written with *)".to_string(),
        };
        return Err(FormulaError::new(*at, *len, what));
    }
    Ok(node)
}

/// One operation of a program, on a stack of values: each binary operation also comes fused with
/// a signal or a number as its right operand (one dispatch where there would be two).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Op {
    Num(f64),
    Sig(u16),
    Neg,
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    AddSig(u16),
    SubSig(u16),
    MulSig(u16),
    DivSig(u16),
    AddNum(f64),
    SubNum(f64),
    MulNum(f64),
    DivNum(f64),
    /// Pushes signal · signal (a `Sig` and the `MulSig` after it).
    SigMulSig(u16, u16),
    /// Pushes number · signal (a `Num` and the `MulSig` after it).
    NumMulSig(f64, u16),
    Call1(Function),
    Call2(Function),
}

impl Op {
    /// Whether it reads a signal.
    fn names_signal(self) -> bool {
        matches!(
            self,
            Op::Sig(_)
                | Op::AddSig(_)
                | Op::SubSig(_)
                | Op::MulSig(_)
                | Op::DivSig(_)
                | Op::SigMulSig(..)
                | Op::NumMulSig(..)
        )
    }

    /// How the operation changes the stack's depth.
    fn depth_change(self) -> isize {
        match self {
            Op::Num(_) | Op::Sig(_) | Op::SigMulSig(..) | Op::NumMulSig(..) => 1,
            Op::Add | Op::Sub | Op::Mul | Op::Div | Op::Pow | Op::Call2(_) => -1,
            _ => 0,
        }
    }
}

fn compile(node: &Node, ops: &mut Vec<Op>) {
    match node {
        Node::Num(v, _) => ops.push(Op::Num(*v)),
        Node::Sig(i) => ops.push(Op::Sig(*i as u16)),
        Node::Neg(x) => {
            compile(x, ops);
            ops.push(Op::Neg);
        }
        Node::Paren(x) => compile(x, ops),
        Node::Bin(op, a, b) => {
            compile(a, ops);
            compile(b, ops);
            // The same operation on the same operands, with one dispatch fewer.
            let fused = match (op, ops.last()) {
                (BinOp::Add, Some(Op::Sig(i))) => Some(Op::AddSig(*i)),
                (BinOp::Sub, Some(Op::Sig(i))) => Some(Op::SubSig(*i)),
                (BinOp::Mul, Some(Op::Sig(i))) => Some(Op::MulSig(*i)),
                (BinOp::Div, Some(Op::Sig(i))) => Some(Op::DivSig(*i)),
                (BinOp::Add, Some(Op::Num(v))) => Some(Op::AddNum(*v)),
                (BinOp::Sub, Some(Op::Num(v))) => Some(Op::SubNum(*v)),
                (BinOp::Mul, Some(Op::Num(v))) => Some(Op::MulNum(*v)),
                (BinOp::Div, Some(Op::Num(v))) => Some(Op::DivNum(*v)),
                _ => None,
            };
            // A product of two leaves is pushed in one step.
            let fused = match (fused, ops.len().checked_sub(2).map(|k| ops[k])) {
                (Some(Op::MulSig(j)), Some(Op::Sig(i))) => {
                    ops.pop();
                    Some(Op::SigMulSig(i, j))
                }
                (Some(Op::MulSig(j)), Some(Op::Num(v))) => {
                    ops.pop();
                    Some(Op::NumMulSig(v, j))
                }
                (f, _) => f,
            };
            match fused {
                Some(f) => *ops.last_mut().expect("an operand") = f,
                None => ops.push(match op {
                    BinOp::Add => Op::Add,
                    BinOp::Sub => Op::Sub,
                    BinOp::Mul => Op::Mul,
                    BinOp::Div => Op::Div,
                    BinOp::Pow => Op::Pow,
                }),
            }
        }
        Node::Call(f, args) => {
            for a in args {
                compile(a, ops);
            }
            ops.push(if f.arity() == 1 {
                Op::Call1(*f)
            } else {
                Op::Call2(*f)
            });
        }
    }
}

/// A compiled formula: its operations in postfix order and the stack depth they need.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    ops: Vec<Op>,
    depth: usize,
}

impl Program {
    /// Compiles a parsed formula; refuses one that costs more than [`MAX_OPS`] operations or needs
    /// a deeper stack than [`MAX_DEPTH`].
    pub fn new(node: &Node) -> Result<Program, FormulaError> {
        let mut ops = Vec::new();
        compile(node, &mut ops);
        if ops.len() > MAX_OPS {
            return Err(FormulaError::new(
                0,
                0,
                format!(
                    "the formula takes {} operations, more than the {MAX_OPS} allowed",
                    ops.len()
                ),
            ));
        }
        let (mut depth, mut deepest) = (0usize, 0usize);
        for op in &ops {
            depth = depth.wrapping_add_signed(op.depth_change());
            deepest = deepest.max(depth);
        }
        if deepest > MAX_DEPTH {
            return Err(FormulaError::new(
                0,
                0,
                format!("the formula nests {deepest} values deep, more than the {MAX_DEPTH} allowed: write it with fewer nested parentheses"),
            ));
        }
        Ok(Program {
            ops,
            depth: deepest,
        })
    }

    /// Parses and compiles `text` as the law of step `step`.
    pub fn parse(text: &str, step: u8) -> Result<Program, FormulaError> {
        Program::new(&parse(text, step)?)
    }

    /// Its value with the signals `s` (indexed as [`NAMES`]); allocates nothing.
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

    /// The operations it takes (its cost per sample).
    pub fn cost(&self) -> usize {
        self.ops.len()
    }

    /// The names it reads, each once, in the order of [`NAMES`].
    pub fn names(&self) -> Vec<usize> {
        let mut used_pair = Vec::new();
        let mut used: Vec<usize> = self
            .ops
            .iter()
            .filter_map(|op| match op {
                Op::Sig(i) | Op::AddSig(i) | Op::SubSig(i) | Op::MulSig(i) | Op::DivSig(i) => {
                    Some(*i as usize)
                }
                Op::NumMulSig(_, j) => Some(*j as usize),
                Op::SigMulSig(i, j) => {
                    used_pair.push(*j as usize);
                    Some(*i as usize)
                }
                _ => None,
            })
            .collect();
        used.append(&mut used_pair);
        used.sort_unstable();
        used.dedup();
        used
    }
}

/// The additive terms of `node` with their signs: x − (y + z) gives [+x, −y, −z]; a negated or
/// parenthesised sum is opened. What the verdict tries one by one when a law differs.
pub fn terms(node: &Node) -> Vec<(f64, &Node)> {
    fn walk<'a>(node: &'a Node, sign: f64, out: &mut Vec<(f64, &'a Node)>) {
        match node {
            Node::Bin(BinOp::Add, a, b) => {
                walk(a, sign, out);
                walk(b, sign, out);
            }
            Node::Bin(BinOp::Sub, a, b) => {
                walk(a, sign, out);
                walk(b, -sign, out);
            }
            Node::Neg(x) => walk(x, -sign, out),
            Node::Paren(x) => walk(x, sign, out),
            _ => out.push((sign, node)),
        }
    }
    let mut out = Vec::new();
    walk(node, 1.0, &mut out);
    out
}

/// `node` as plain text, with the names and a centred dot for the product: how a verdict quotes
/// a term.
pub fn text(node: &Node) -> String {
    fn wrap(node: &Node, least: u8) -> String {
        if precedence(node) < least {
            format!("({})", text(node))
        } else {
            text(node)
        }
    }
    match node {
        Node::Num(_, written) => written.clone(),
        Node::Sig(i) => NAMES[*i].name.to_string(),
        Node::Neg(x) => format!("−{}", wrap(x, 3)),
        Node::Paren(x) => format!("({})", text(x)),
        Node::Bin(BinOp::Add, a, b) => format!("{} + {}", text(a), text(b)),
        Node::Bin(BinOp::Sub, a, b) => format!("{} − {}", text(a), wrap(b, 2)),
        Node::Bin(BinOp::Mul, a, b) => format!("{}·{}", wrap(a, 2), wrap(b, 3)),
        Node::Bin(BinOp::Div, a, b) => format!("{}/{}", wrap(a, 2), wrap(b, 3)),
        Node::Bin(BinOp::Pow, a, b) => format!("{}^{}", wrap(a, 5), wrap(b, 4)),
        Node::Call(f, args) => format!(
            "{}({})",
            f.name(),
            args.iter().map(text).collect::<Vec<_>>().join(", ")
        ),
    }
}

/// Operator precedence for the TeX: 1 sum, 2 product, 3 unary minus, 4 power, 5 atom.
fn precedence(node: &Node) -> u8 {
    match node {
        Node::Bin(BinOp::Add | BinOp::Sub, ..) => 1,
        Node::Bin(BinOp::Mul | BinOp::Div, ..) => 2,
        Node::Neg(_) => 3,
        Node::Bin(BinOp::Pow, ..) => 4,
        _ => 5,
    }
}

/// `node` in TeX, as KaTeX typesets it: the names as the walkthrough writes them, products with
/// a centred dot, quotients as fractions and the formula's own parentheses kept.
pub fn tex(node: &Node) -> String {
    fn wrap(node: &Node, least: u8) -> String {
        if precedence(node) < least {
            format!(r"\left({}\right)", tex(node))
        } else {
            tex(node)
        }
    }
    match node {
        Node::Num(_, written) => match written.split_once(['e', 'E']) {
            Some((m, e)) => format!(r"{m}\cdot 10^{{{}}}", e.trim_start_matches('+')),
            None => written.clone(),
        },
        Node::Sig(i) => NAMES[*i].tex.to_string(),
        Node::Neg(x) => format!("-{}", wrap(x, 3)),
        Node::Paren(x) => format!(r"\left({}\right)", tex(x)),
        Node::Bin(BinOp::Add, a, b) => format!("{} + {}", tex(a), tex(b)),
        Node::Bin(BinOp::Sub, a, b) => format!("{} - {}", tex(a), wrap(b, 2)),
        Node::Bin(BinOp::Mul, a, b) => format!(r"{} \cdot {}", wrap(a, 2), wrap(b, 3)),
        Node::Bin(BinOp::Div, a, b) => format!(r"\frac{{{}}}{{{}}}", tex(a), tex(b)),
        Node::Bin(BinOp::Pow, a, b) => format!("{{{}}}^{{{}}}", wrap(a, 5), tex(b)),
        Node::Call(Function::Sqrt, args) => format!(r"\sqrt{{{}}}", tex(&args[0])),
        Node::Call(Function::Abs, args) => format!(r"\left|{}\right|", tex(&args[0])),
        Node::Call(f, args) => format!(
            r"\operatorname{{{}}}\left({}\right)",
            f.name(),
            args.iter().map(tex).collect::<Vec<_>>().join(", ")
        ),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn bad_formulas_are_refused_at_their_place_with_the_reason() {
        let cases: &[(&str, u8, usize, &str)] = &[
            ("", 1, 0, "empty"),
            ("1 +", 1, 4, "ends where"),
            ("(1 + 2", 1, 1, "never closed"),
            ("1 + 2)", 1, 6, "no '('"),
            ("2 x1h", 1, 3, "expected an operator"),
            ("foo + 1", 1, 1, "unknown name 'foo'"),
            ("z2 + 1", 1, 1, "not known in step 1"),
            ("1 + z4", 3, 5, "not known in step 3"),
            ("sqrt(1, 2)", 1, 1, "takes 1 argument"),
            ("sqr(2)", 1, 1, "no function 'sqr'"),
            ("sqrt + 1", 1, 1, "is a function"),
            ("1 / 0", 1, 3, "division by zero"),
            ("x1h/(2 - 2)", 1, 4, "division by zero"),
            ("1 $ 2", 1, 3, "not part of the language"),
            ("1e999", 1, 1, "too large"),
            ("* 2", 1, 1, "where a number"),
        ];
        for (text, step, at, needle) in cases {
            let e = parse(text, *step).expect_err(text);
            assert_eq!(e.at, *at, "{text}: {e}");
            assert!(e.reason.contains(needle), "{text}: {e}");
        }
        let long = "x1h + ".repeat(400) + "1";
        assert!(parse(&long, 1).unwrap_err().reason.contains("characters"));
        let costly = "x1h*x1h*x1h + ".repeat(140) + "1";
        assert!(Program::parse(&costly, 1)
            .unwrap_err()
            .reason
            .contains("operations"));
        let deep = "(".repeat(40) + "1" + &")".repeat(40);
        // Parentheses alone push nothing; a chain of powers does.
        assert!(Program::parse(&deep, 1).is_ok());
        let deep = "2^".repeat(40) + "1";
        assert!(Program::parse(&deep, 1)
            .unwrap_err()
            .reason
            .contains("deep"));
        // The parser follows at most MAX_NESTING levels: deeper input is refused, not recursed.
        let nested = "(".repeat(900) + "1" + &")".repeat(900);
        let e = parse(&nested, 1).unwrap_err();
        assert!(
            e.reason.contains("nests deeper") && e.at == MAX_NESTING + 1,
            "{e}"
        );
    }

    #[test]
    fn every_name_is_unique_and_documented() {
        for (i, n) in NAMES.iter().enumerate() {
            assert_eq!(index(n.name), Some(i), "{}", n.name);
            assert!(!n.doc.is_empty() && !n.tex.is_empty(), "{}", n.name);
            assert!((1..=4).contains(&n.from_step));
            assert!(FUNCTIONS.iter().all(|f| f.0 != n.name));
        }
    }

    #[test]
    fn terms_open_sums_and_keep_their_signs() {
        let node = parse("a - (b1 + c) + -(d - e*f)", 4);
        assert!(node.is_err(), "b1 is not a name");
        let node = parse("x2 - (x3 + z1) + -(z3 - a1*a3)", 4).unwrap();
        let t: Vec<(f64, String)> = terms(&node).iter().map(|(s, n)| (*s, tex(n))).collect();
        assert_eq!(
            t,
            [
                (1.0, "x_2".into()),
                (-1.0, "x_3".into()),
                (-1.0, "z_1".into()),
                (-1.0, "z_3".into()),
                (1.0, r"a_1 \cdot a_3".into()),
            ]
        );
    }

    #[test]
    fn tex_writes_the_names_and_the_structure() {
        let t = |s: &str| tex(&parse(s, 4).unwrap());
        assert_eq!(t("-k1s1*z1"), r"-k_{1s1} \cdot z_1");
        assert_eq!(
            t("x1h/(2*a3)"),
            r"\frac{\hat{x}_1}{\left(2 \cdot a_3\right)}"
        );
        assert_eq!(t("a1 - (x2 - x3)"), r"a_1 - \left(x_2 - x_3\right)");
        assert_eq!(t("sqrt(x4h^2)"), r"\sqrt{{\hat{x}_4}^{2}}");
        assert_eq!(
            t("sat(z1, 1e3)"),
            r"\operatorname{sat}\left(z_1, 1\cdot 10^{3}\right)"
        );
        assert_eq!(t("-(x2 + x3)"), r"-\left(x_2 + x_3\right)");
    }
}
