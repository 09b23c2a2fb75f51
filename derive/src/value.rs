//! Exact evaluation of attribute values: integers, decimals (`0.35` is `7/20`), fractions
//! `a/b`, and `+ - * /` with parentheses. No value passes through a float.

use num_traits::Zero;
use planar_arm_core::ring::{parse_decimal, Rational};
use syn::{BinOp, Expr, Lit, UnOp};

/// The exact value of `expr`, or an error spanning the offending tokens.
pub fn eval(expr: &Expr) -> syn::Result<Rational> {
    match expr {
        Expr::Lit(lit) => match &lit.lit {
            Lit::Int(i) => literal(i.base10_digits(), i.suffix(), &lit.lit),
            Lit::Float(f) => literal(f.base10_digits(), f.suffix(), &lit.lit),
            Lit::Str(_) => Err(syn::Error::new_spanned(
                lit,
                "expected a number, found a string; write the value without quotes, e.g. 0.35 or 3/2",
            )),
            other => Err(syn::Error::new_spanned(
                other,
                "expected a number such as 1, 0.35 or 3/2",
            )),
        },
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Ok(-eval(&u.expr)?),
        Expr::Paren(p) => eval(&p.expr),
        Expr::Group(g) => eval(&g.expr),
        Expr::Binary(b) => {
            let (l, r) = (eval(&b.left)?, eval(&b.right)?);
            match b.op {
                BinOp::Add(_) => Ok(l + r),
                BinOp::Sub(_) => Ok(l - r),
                BinOp::Mul(_) => Ok(l * r),
                BinOp::Div(_) if r.is_zero() => Err(syn::Error::new_spanned(
                    &b.right,
                    "division by zero; the divisor of a link parameter must not be zero",
                )),
                BinOp::Div(_) => Ok(l / r),
                _ => Err(syn::Error::new_spanned(
                    b.op,
                    "unsupported operator; link parameters allow + - * / and parentheses",
                )),
            }
        }
        Expr::Path(p) => Err(syn::Error::new_spanned(
            p,
            format!(
                "expected a number, found `{}`; write the value itself (1, 0.35, 3/2): \
                 parameters are evaluated exactly at compile time and cannot name constants",
                quote::quote!(#p).to_string().replace(' ', "")
            ),
        )),
        Expr::Call(_) | Expr::MethodCall(_) | Expr::Macro(_) => Err(syn::Error::new_spanned(
            expr,
            "expected a number, found a call; parameters are evaluated exactly at compile time, \
             so only numbers, + - * / and parentheses are allowed",
        )),
        Expr::Cast(c) => Err(syn::Error::new_spanned(
            c,
            "expected a number, found a cast; remove the `as ...`",
        )),
        other => Err(syn::Error::new_spanned(
            other,
            "expected a number such as 1, 0.35 or 3/2",
        )),
    }
}

fn literal(digits: &str, suffix: &str, span: &Lit) -> syn::Result<Rational> {
    if !matches!(
        suffix,
        "" | "f64" | "f32" | "i32" | "i64" | "u32" | "u64" | "usize" | "isize"
    ) {
        return Err(syn::Error::new_spanned(
            span,
            format!("unsupported suffix `{suffix}`; write the number without it"),
        ));
    }
    parse_decimal(digits).ok_or_else(|| {
        syn::Error::new_spanned(
            span,
            "number out of range; link parameters must be ordinary magnitudes such as 0.001 to 1000",
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use planar_arm_core::ring::ratio;

    fn ev(s: &str) -> syn::Result<Rational> {
        eval(&syn::parse_str(s).unwrap())
    }

    #[test]
    fn values_are_exact() {
        assert_eq!(ev("0.35").unwrap(), ratio(7, 20));
        assert_eq!(ev("3/2").unwrap(), ratio(3, 2));
        assert_eq!(ev("-(1 + 1) / 4").unwrap(), ratio(-1, 2));
        assert_eq!(ev("9.80665").unwrap(), ratio(980_665, 100_000));
        assert_eq!(ev("1_000").unwrap(), ratio(1000, 1));
        assert!(ev("1/0").is_err());
        assert!(ev("\"1\"").is_err());
        assert!(ev("foo").is_err());
    }
}
