//! The derived formulas as the emitted impl shows them: readable in the methods' doc
//! comments, and exact in `i128` and `f64`, which every coefficient must fit.

use std::fmt::Write as _;

use num_traits::Zero;

use super::error::EmitError;
use crate::expr::Expr;
use crate::methods::Derived;
use crate::programs::method::two;
use crate::ring::{show, to_f64, to_i128_pair};
use crate::slp::Emit;

/// A method's doc comment when its formulas, of `terms` terms, are past [`DOC_TERMS`]: formulas
/// this long are not read in rustdoc, and formatting them costs every user compile time.
#[must_use]
pub fn long_formula_doc(title: &str, terms: usize) -> String {
    format!(
        "{title}\n\nThe exact formulas have {terms} terms, more than the {DOC_TERMS} shown \
         in the documentation; the arm's `EXACT` holds them exactly (each entry prints with \
         `Display`), and `planar_arm::symbolic` (feature `symbolic`) derives them."
    )
}

/// Human-readable formulas for a method's doc comment.
#[must_use]
pub fn formula_doc<C: Emit>(title: &str, rows: &[(String, &Expr<C>)]) -> String {
    let terms: usize = rows.iter().map(|(_, e)| e.len()).sum();
    if terms > DOC_TERMS {
        return long_formula_doc(title, terms);
    }
    let mut s = format!("{title}\n\n```text\n");
    for (name, e) in rows {
        let _ = writeln!(s, "{name} = {e}");
    }
    s.push_str("```\n");
    s
}

/// The most terms a method's documentation prints: every formula of an arm of up to four
/// links; at six links the longest (736 terms) is left to `EXACT`. Formatting the formulas,
/// and expanding C only to print it, was a fifth of an unoptimised 6-link derive at 2,000.
pub const DOC_TERMS: usize = 500;

/// Fails if a derived coefficient cannot be emitted as `const` data (`i128`) or as `f64`.
///
/// # Errors
/// Names the first entry whose coefficient does not fit.
pub fn check_representable<C: Emit>(d: &Derived<C>) -> Result<(), EmitError> {
    let check = |what: &str, e: &Expr<C>| -> Result<(), EmitError> {
        for (_, _, c) in e
            .terms()
            .flat_map(|(m, t, c)| c.parts().into_iter().map(move |(_, r)| (m, t, r)))
        {
            let c = &c;
            if to_i128_pair(c).is_none() || to_f64(c).is_none() || c.is_zero() {
                return Err(EmitError {
                    message: format!(
                        "the exact coefficient {} in {what} does not fit in i128 and f64; \
                         choose link parameters with smaller numerators and denominators",
                        show(c)
                    ),
                });
            }
        }
        Ok(())
    };
    check("the kinetic energy", &d.dynamics.kinetic_energy)?;
    check("the potential energy", &d.dynamics.potential_energy)?;
    for (i, row) in d.dynamics.mass_matrix.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            check(&format!("M{}", two(i, j)), e)?;
        }
    }
    for (i, e) in d.dynamics.coriolis.iter().enumerate() {
        check(&format!("c{}", i + 1), e)?;
    }
    for (i, e) in d.dynamics.gravity.iter().enumerate() {
        check(&format!("g{}", i + 1), e)?;
    }
    Ok(())
}
