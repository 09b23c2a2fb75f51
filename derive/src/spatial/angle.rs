//! Angles in spatial attributes: numbers of radians and rational multiples of `pi`, exactly.
//! `pi/2`, `-pi/2`, `2*pi/3` and `0.3` are exact; a mix such as `pi/2 + 0.1` is a number of
//! radians known to rounding.

use planar_arm_core::ring::{parse_decimal, Rational};
use syn::{BinOp, Expr, Lit, UnOp};

/// An angle `radians + pi_multiple * pi`, both exact rationals.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Angle {
    pub radians: Rational,
    pub pi_multiple: Rational,
}

impl Angle {
    fn number(r: Rational) -> Self {
        Self {
            radians: r,
            pi_multiple: Rational::from_integer(0.into()),
        }
    }

    fn is_number(&self) -> bool {
        num_traits::Zero::is_zero(&self.pi_multiple)
    }
}

/// The exact angle of `expr`, or an error spanning the tokens that are not a number, `pi`,
/// `+ - * /` or parentheses.
pub fn eval(expr: &Expr) -> syn::Result<Angle> {
    eval_at(expr, 0)
}

const MAX_DEPTH: usize = 64;

fn eval_at(expr: &Expr, depth: usize) -> syn::Result<Angle> {
    let bad = |message: &str| Err(syn::Error::new_spanned(expr, message));
    if depth > MAX_DEPTH {
        return bad("angle nested too deeply; simplify it");
    }
    match expr {
        Expr::Lit(lit) => {
            let (digits, suffix) = match &lit.lit {
                Lit::Int(i) => (i.base10_digits(), i.suffix()),
                Lit::Float(f) => (f.base10_digits(), f.suffix()),
                Lit::Str(_) => {
                    return bad(
                        "expected an angle, found a string; write it without quotes: a number of \
                     radians, or a multiple of `pi` such as `pi/2`",
                    )
                }
                _ => return bad(
                    "expected an angle: a number of radians, or a multiple of `pi` such as `pi/2`",
                ),
            };
            // `90deg` lexes as 90 with a suffix: read as radians, it would be silently wrong.
            if !suffix.is_empty() {
                return bad(&format!(
                    "unsupported suffix `{suffix}`; an angle is a number of radians or a multiple \
                     of `pi` (90 degrees is `pi/2`)"
                ));
            }
            parse_decimal(digits)
                .map(Angle::number)
                .ok_or_else(|| syn::Error::new_spanned(expr, "angle out of range"))
        }
        Expr::Path(p) if p.path.is_ident("pi") || p.path.is_ident("PI") => Ok(Angle {
            radians: Rational::from_integer(0.into()),
            pi_multiple: Rational::from_integer(1.into()),
        }),
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => {
            let a = eval_at(&u.expr, depth + 1)?;
            Ok(Angle {
                radians: -a.radians,
                pi_multiple: -a.pi_multiple,
            })
        }
        Expr::Paren(p) => eval_at(&p.expr, depth + 1),
        Expr::Group(g) => eval_at(&g.expr, depth + 1),
        Expr::Binary(b) => {
            let (l, r) = (eval_at(&b.left, depth + 1)?, eval_at(&b.right, depth + 1)?);
            match b.op {
                BinOp::Add(_) => Ok(Angle {
                    radians: l.radians + r.radians,
                    pi_multiple: l.pi_multiple + r.pi_multiple,
                }),
                BinOp::Sub(_) => Ok(Angle {
                    radians: l.radians - r.radians,
                    pi_multiple: l.pi_multiple - r.pi_multiple,
                }),
                BinOp::Mul(_) if l.is_number() => Ok(Angle {
                    radians: &l.radians * &r.radians,
                    pi_multiple: &l.radians * &r.pi_multiple,
                }),
                BinOp::Mul(_) if r.is_number() => Ok(Angle {
                    radians: &l.radians * &r.radians,
                    pi_multiple: &l.pi_multiple * &r.radians,
                }),
                BinOp::Mul(_) => bad("`pi` times `pi` is not an angle"),
                BinOp::Div(_) if !r.is_number() => bad("an angle cannot be divided by `pi`"),
                BinOp::Div(_) if num_traits::Zero::is_zero(&r.radians) => bad("division by zero"),
                BinOp::Div(_) => Ok(Angle {
                    radians: &l.radians / &r.radians,
                    pi_multiple: &l.pi_multiple / &r.radians,
                }),
                _ => bad("angles allow + - * /, parentheses, numbers and `pi`"),
            }
        }
        // alpha = foo, alpha = FRAC_PI_2
        Expr::Path(p) => bad(&format!(
            "expected an angle, found `{}`; write a number of radians or a multiple of `pi` such \
             as `pi/2`: angles are evaluated exactly at compile time and cannot name constants",
            quote::quote!(#p).to_string().replace(' ', ""),
        )),
        Expr::Field(_) => bad(
            "an angle must be a number (`pi/2`, `0.3`), not a run-time parameter: the derive \
             simplifies the geometry with its exact value",
        ),
        _ => bad("expected an angle: a number of radians, or a multiple of `pi` such as `pi/2`"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use planar_arm_core::ring::ratio;

    fn ev(s: &str) -> syn::Result<Angle> {
        eval(&syn::parse_str(s).unwrap())
    }

    #[test]
    fn multiples_of_pi_are_exact() {
        let a = ev("-pi/2").unwrap();
        assert_eq!((a.radians, a.pi_multiple), (ratio(0, 1), ratio(-1, 2)));
        let a = ev("2*pi/3 + 0.5").unwrap();
        assert_eq!((a.radians, a.pi_multiple), (ratio(1, 2), ratio(2, 3)));
        assert_eq!(ev("pi * 3 / 4").unwrap().pi_multiple, ratio(3, 4));
        assert!(ev("pi * pi").is_err());
        assert!(ev("1 / pi").is_err());
        assert!(ev("self.alpha").is_err());
        assert!(ev("\"pi\"").is_err());
        assert!(ev("90deg").is_err());
        assert!(ev("1.5f64").is_err());
    }
}
