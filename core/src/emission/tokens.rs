//! Tokens of exact constants and of paths, built as token trees: the rendered bodies are
//! assembled from them without a `quote!` per operator.

use num_traits::{Signed, ToPrimitive};
use proc_macro2::{Delimiter, Group, Ident, Literal, Punct, Spacing, Span, TokenStream, TokenTree};

use super::error::EmitError;
use crate::ring::{show, to_f64, Rational};

/// `f64` tokens of an exact constant: `2.0`, `(10.0 / 3.0)`, or the nearest `f64` when the
/// numerator or denominator is not exact in `f64`.
///
/// # Errors
/// If the value is outside the finite `f64` range.
pub fn f64_tokens(r: &Rational) -> Result<TokenStream, EmitError> {
    Ok(wrapped(constant_inner(r)?).into_iter().collect())
}

/// `f64` tokens of a value known only as an `f64` (a cosine the derive computed): the shortest
/// literal that reads back as the same `f64`, negated in parentheses.
///
/// # Errors
/// If the value is not finite.
pub fn f64_value_tokens(x: f64) -> Result<TokenStream, EmitError> {
    if !x.is_finite() {
        return Err(EmitError {
            message: format!("the constant {x} is not a finite f64"),
        });
    }
    let literal: TokenStream = match named_constant(x.abs()) {
        Some(name) => quote::quote!(::core::f64::consts::#name),
        None => TokenTree::from(Literal::f64_unsuffixed(x.abs())).into(),
    };
    Ok(if x.is_sign_negative() && x != 0.0 {
        let inner: TokenStream = core::iter::once(punct('-')).chain(literal).collect();
        TokenStream::from(TokenTree::from(Group::new(Delimiter::Parenthesis, inner)))
    } else {
        literal
    })
}

/// The `core::f64::consts` name of a twist or joint offset such as π/2 or π/4, so the
/// generated code reads as the angle it is (and clippy does not mistake a digit string for a
/// mistyped constant).
fn named_constant(x: f64) -> Option<Ident> {
    use core::f64::consts as c;
    let named = [
        (c::PI, "PI"),
        (c::TAU, "TAU"),
        (c::FRAC_PI_2, "FRAC_PI_2"),
        (c::FRAC_PI_3, "FRAC_PI_3"),
        (c::FRAC_PI_4, "FRAC_PI_4"),
        (c::FRAC_PI_6, "FRAC_PI_6"),
        (c::FRAC_PI_8, "FRAC_PI_8"),
        (c::SQRT_2, "SQRT_2"),
        (c::FRAC_1_SQRT_2, "FRAC_1_SQRT_2"),
    ];
    named
        .iter()
        .find(|(v, _)| v.to_bits() == x.to_bits())
        .map(|(_, name)| Ident::new(name, Span::call_site()))
}

/// An `f64` constant as an expression in its own right, as a function's argument is:
/// `2.0`, `10.0 / 3.0`, `-(10.0 / 3.0)`.
pub(crate) fn f64_argument_tokens(r: &Rational) -> Result<TokenStream, EmitError> {
    Ok(constant_inner(r)?.into_iter().collect())
}

/// A constant's tokens without outer parentheses: `2.0`, `10.0 / 3.0`, `-2.0`, `-(10.0 / 3.0)`.
pub(super) fn constant_inner(r: &Rational) -> Result<Vec<TokenTree>, EmitError> {
    const EXACT: u64 = 1 << 53;
    let value = to_f64(r).ok_or_else(|| EmitError {
        message: format!("the constant {} does not fit in f64", show(r)),
    })?;
    let magnitude = r.abs();
    let num = magnitude.numer().to_u64().filter(|&v| v <= EXACT);
    let den = magnitude.denom().to_u64().filter(|&v| v <= EXACT);
    let body: Vec<TokenTree> = match (num, den) {
        #[allow(clippy::cast_precision_loss)] // both are at most 2^53, exact in f64
        (Some(a), Some(1)) => vec![Literal::f64_unsuffixed(a as f64).into()],
        #[allow(clippy::cast_precision_loss)]
        (Some(a), Some(b)) => vec![
            Literal::f64_unsuffixed(a as f64).into(),
            punct('/'),
            Literal::f64_unsuffixed(b as f64).into(),
        ],
        _ => vec![Literal::f64_unsuffixed(value.abs()).into()],
    };
    Ok(if r.is_negative() {
        vec![punct('-'), atom(body)]
    } else {
        body
    })
}

/// The tokens as one operand: themselves if they are one token tree, else in parentheses.
fn atom(mut tokens: Vec<TokenTree>) -> TokenTree {
    if tokens.len() == 1 {
        if let Some(t) = tokens.pop() {
            return t;
        }
    }
    Group::new(Delimiter::Parenthesis, tokens.into_iter().collect()).into()
}

/// [`atom`] as a token list.
pub(super) fn wrapped(tokens: Vec<TokenTree>) -> Vec<TokenTree> {
    vec![atom(tokens)]
}

pub(super) fn punct(c: char) -> TokenTree {
    Punct::new(c, Spacing::Alone).into()
}

/// `::a::b::c` (every segment at the call site, as `quote!` writes it).
pub(super) fn path(segments: &[&str]) -> Vec<TokenTree> {
    let mut out = Vec::with_capacity(3 * segments.len());
    for s in segments {
        out.push(Punct::new(':', Spacing::Joint).into());
        out.push(Punct::new(':', Spacing::Alone).into());
        out.push(Ident::new(s, Span::call_site()).into());
    }
    out
}
