//! The first stage: the exact algebra every later stage computes in. Coefficients
//! ([`ring`], and [`poly`] for run-time parameters), trigonometric atoms of joint-angle sums
//! ([`trig`]) and the canonical sums of terms built from them ([`expr`]); residues modulo
//! word-sized primes for exact linear algebra on large matrices ([`residue`]).

pub mod expr;
mod monomial;
pub mod poly;
pub mod residue;
pub mod ring;
pub mod trig;
