//! Exact evaluation of attribute values: integers, decimals (`0.35` is `7/20`), fractions
//! `a/b`, `+ - * /` with parentheses, and run-time parameters `self.NAME`. No value passes
//! through a float; a value with parameters is a polynomial in them ([`Poly`]).

use planar_arm_core::ring::{parse_decimal, Rational};
use planar_arm_core::{Param, Poly};
use syn::{BinOp, Expr, Lit, UnOp};

/// A run-time parameter named in a value: its field name and the `self.NAME` tokens.
pub struct ParamUse {
    pub name: String,
    pub tokens: proc_macro2::TokenStream,
}

/// The exact value of `expr`, or an error spanning the offending tokens. Every `self.NAME`
/// met is recorded in `params` (whether the field exists is checked by the caller).
pub fn eval(expr: &Expr, params: &mut Vec<ParamUse>) -> syn::Result<Poly> {
    eval_at(expr, params, 0)
}

/// The deepest nesting of parentheses, signs and operators of different precedence that a value
/// may have. Chains of one operator (`1 + 1 + ... + 1`) are walked without recursion, so this
/// bounds only what a person would nest by hand; past it, the derive's stack, which the
/// compiler's own thread provides, would run out.
const MAX_DEPTH: usize = 200;

fn eval_at(expr: &Expr, params: &mut Vec<ParamUse>, depth: usize) -> syn::Result<Poly> {
    if depth > MAX_DEPTH {
        return Err(syn::Error::new_spanned(
            expr,
            format!(
                "value nested more than {MAX_DEPTH} levels deep; simplify it (compute the number \
                 first), or read it at run time from an f64 field: `self.field`"
            ),
        ));
    }
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
        Expr::Unary(u) if matches!(u.op, UnOp::Neg(_)) => Ok(-eval_at(&u.expr, params, depth + 1)?),
        Expr::Paren(p) => eval_at(&p.expr, params, depth + 1),
        Expr::Group(g) => eval_at(&g.expr, params, depth + 1),
        Expr::Binary(b) => {
            // `a + b - c + ...` nests to the left, one level per operator: walk that spine in a
            // loop, then fold left to right.
            let level = precedence(&b.op);
            let mut rights = Vec::new();
            let mut left = expr;
            while let Expr::Binary(b) = left {
                if level.is_none() || precedence(&b.op) != level {
                    break;
                }
                rights.push(b);
                left = &b.left;
            }
            if rights.is_empty() {
                // An operator outside + - * /.
                return Err(unsupported(b));
            }
            let mut value = eval_at(left, params, depth + 1)?;
            for b in rights.into_iter().rev() {
                let right = eval_at(&b.right, params, depth + 1)?;
                value = apply(b, value, right)?;
            }
            Ok(value)
        }
        // self.m1
        Expr::Field(f) if is_self(&f.base) => match &f.member {
            syn::Member::Named(name) => {
                params.push(ParamUse {
                    name: name.to_string(),
                    tokens: quote::quote!(#f),
                });
                Ok(Poly::param(Param::new(&name.to_string())))
            }
            syn::Member::Unnamed(_) => Err(syn::Error::new_spanned(
                f,
                "a run-time parameter is a named `f64` field of the struct: `self.name`",
            )),
        },
        Expr::Path(p) => Err(syn::Error::new_spanned(
            p,
            format!(
                "expected a number, found `{}`; write the value itself (1, 0.35, 3/2): values are \
                 evaluated exactly at compile time and cannot name constants; to read a value at \
                 run time, name an `f64` field of the struct: `self.field`",
                quote::quote!(#p).to_string().replace(' ', ""),
            ),
        )),
        Expr::Call(_) | Expr::MethodCall(_) | Expr::Macro(_) => Err(syn::Error::new_spanned(
            expr,
            "expected a number, found a call; values are numbers, `self.field` (an f64 field \
             read at run time), + - * / and parentheses",
        )),
        Expr::Cast(c) => Err(syn::Error::new_spanned(
            c,
            "expected a number, found a cast; remove the `as ...`",
        )),
        other => Err(syn::Error::new_spanned(
            other,
            "expected a number such as 1, 0.35 or 3/2, or `self.field`",
        )),
    }
}

/// `Some(0)` for `+ -`, `Some(1)` for `* /`, `None` for the operators values do not allow.
fn precedence(op: &BinOp) -> Option<u8> {
    match op {
        BinOp::Add(_) | BinOp::Sub(_) => Some(0),
        BinOp::Mul(_) | BinOp::Div(_) => Some(1),
        _ => None,
    }
}

fn unsupported(b: &syn::ExprBinary) -> syn::Error {
    syn::Error::new_spanned(
        b.op,
        "unsupported operator; link parameters allow + - * / and parentheses",
    )
}

/// `l op r` for the operator of `b` (one of + - * /).
fn apply(b: &syn::ExprBinary, l: Poly, r: Poly) -> syn::Result<Poly> {
    match b.op {
        BinOp::Add(_) => Ok(l + r),
        BinOp::Sub(_) => Ok(l - r),
        BinOp::Mul(_) => Ok(l * r),
        BinOp::Div(_) => match r.as_rational() {
            Some(d) if num_traits::Zero::is_zero(&d) => Err(syn::Error::new_spanned(
                &b.right,
                "division by zero; the divisor of a link parameter must not be zero",
            )),
            Some(d) => Ok(planar_arm_core::Coefficient::scale(
                &l,
                &(Rational::from_integer(1.into()) / d),
            )),
            None => Err(syn::Error::new_spanned(
                &b.right,
                "division by a run-time parameter is not supported: values must stay \
                 polynomial in the parameters so that the derivation is exact; divide \
                 by a number, or make the quotient itself the parameter (an f64 field)",
            )),
        },
        _ => Err(unsupported(b)),
    }
}

fn is_self(e: &Expr) -> bool {
    matches!(e, Expr::Path(p) if p.qself.is_none() && p.path.is_ident("self"))
}

/// The most digits, and the largest exponent, of one literal. Exact arithmetic on a value
/// costs time in its size: with this bound every value is at most a few thousand bits per
/// literal in it, where `1e100000` multiplied sixteen times took minutes.
const MAX_DIGITS: usize = 400;

fn ordinary_size(digits: &str) -> bool {
    let (mantissa, exponent) = match digits.find(['e', 'E']) {
        Some(i) => (&digits[..i], Some(&digits[i + 1..])),
        None => (digits, None),
    };
    let exponent_ok = exponent.is_none_or(|e| {
        let e = e.trim_start_matches(['+', '-']).trim_start_matches('0');
        // An empty exponent is zero; syn has checked that the rest are digits.
        e.len() <= 3 && e.parse::<usize>().map_or(true, |v| v <= MAX_DIGITS)
    });
    exponent_ok && mantissa.bytes().filter(u8::is_ascii_digit).count() <= MAX_DIGITS
}

fn literal(digits: &str, suffix: &str, span: &Lit) -> syn::Result<Poly> {
    if !matches!(
        suffix,
        "" | "f64" | "f32" | "i32" | "i64" | "u32" | "u64" | "usize" | "isize"
    ) {
        return Err(syn::Error::new_spanned(
            span,
            format!("unsupported suffix `{suffix}`; write the number without it"),
        ));
    }
    if !ordinary_size(digits) {
        return Err(syn::Error::new_spanned(
            span,
            format!(
                "number out of range; a literal may have at most {MAX_DIGITS} digits and an \
                 exponent of at most {MAX_DIGITS} (f64 spans about 1e-324 to 1e308)"
            ),
        ));
    }
    parse_decimal(digits).map(Poly::constant).ok_or_else(|| {
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

    fn ev(s: &str) -> syn::Result<Poly> {
        eval(&syn::parse_str(s).unwrap(), &mut Vec::new())
    }

    #[test]
    fn values_are_exact() {
        assert_eq!(ev("0.35").unwrap(), Poly::constant(ratio(7, 20)));
        assert_eq!(ev("3/2").unwrap(), Poly::constant(ratio(3, 2)));
        assert_eq!(ev("-(1 + 1) / 4").unwrap(), Poly::constant(ratio(-1, 2)));
        assert_eq!(
            ev("9.80665").unwrap(),
            Poly::constant(ratio(980_665, 100_000))
        );
        assert_eq!(ev("1_000").unwrap(), Poly::constant(ratio(1000, 1)));
        assert!(ev("1/0").is_err());
        assert!(ev("\"1\"").is_err());
        assert!(ev("foo").is_err());
        assert_eq!(ev("1e400 / 1e400").unwrap(), Poly::constant(ratio(1, 1)));
        assert_eq!(ev("2.5E-0").unwrap(), Poly::constant(ratio(5, 2)));
        assert!(ev("1e401").is_err());
        assert!(ev("1e-401").is_err());
        assert!(ev(&"7".repeat(401)).is_err());
        assert!(ev("1 % 2").is_err());
        assert_eq!(
            ev("2 * 3 / 4 - 1 + 1 / 2").unwrap(),
            Poly::constant(ratio(1, 1))
        );
    }

    #[test]
    fn long_chains_do_not_recurse() {
        // 20 000 terms: a recursive evaluator overflowed the compiler's stack here. Parsed and
        // evaluated on a thread with a small stack, as a check that the depth stays bounded.
        let text = vec!["1"; 20_000].join(" + ");
        let result = std::thread::Builder::new()
            .stack_size(1 << 20)
            .spawn(move || {
                let expr: Expr = syn::parse_str(&text).unwrap();
                let value = ev_expr(&expr);
                // syn drops the nested chain recursively: keep it alive past the check.
                std::mem::forget(expr);
                value
            })
            .unwrap()
            .join()
            .unwrap();
        assert_eq!(result.unwrap(), Poly::constant(ratio(20_000, 1)));
        let deep = format!("{}1{}", "(".repeat(300), ")".repeat(300));
        let err = ev(&deep).unwrap_err().to_string();
        assert!(err.contains("nested more than 200 levels"), "{err}");
    }

    fn ev_expr(e: &Expr) -> syn::Result<Poly> {
        eval(e, &mut Vec::new())
    }

    #[test]
    fn parameters_stay_polynomial() {
        let mut uses = Vec::new();
        let v = eval(
            &syn::parse_str("self.m * self.l / 2 + 1").unwrap(),
            &mut uses,
        )
        .unwrap();
        assert_eq!(v.to_string(), "(1 + 1/2 l m)");
        assert_eq!(uses.len(), 2);
        assert!(ev("1 / self.m").is_err());
        assert!(ev("self.0").is_err());
    }
}
