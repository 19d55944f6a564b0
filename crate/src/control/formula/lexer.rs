//! The lexer: a formula's text cut into numbers, names and operators.

use super::FormulaError;
use crate::text::{excerpt, Message};

#[derive(Clone, Debug, PartialEq)]
pub(super) enum Token {
    Num(f64, String),
    Ident(String),
    Op(char),
}

/// The tokens of `text`, each with its first character (from 1) and its length in characters.
pub(super) fn tokens(text: &str) -> Result<Vec<(Token, usize, usize)>, FormulaError> {
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
                FormulaError::new(
                    start + 1,
                    i - start,
                    Message::new("formula-not-a-number").text("written", written.as_str()),
                )
            })?;
            if !value.is_finite() {
                return Err(FormulaError::new(
                    start + 1,
                    i - start,
                    Message::new("formula-number-too-large").text("written", written),
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
                    Message::new("formula-not-in-language").text("char", excerpt(&c.to_string())),
                ))
            }
        };
        out.push((Token::Op(op), start + 1, 1));
        i += 1;
    }
    Ok(out)
}
