//! The compact encoding of exact expressions in the `EXACT` const data.
//!
//! Written as one literal per expression, `planar_arm::exact::Terms` decodes it. A ten-link
//! arm's derivation has about 8,000 terms; emitted as a const slice with one constructor call
//! per term it cost the user's compiler about three times the rest of the derive's output in
//! time and ten times in memory (docs/performance.md). As a byte string it is one token.
//!
//! Each term is a sequence of numbers: the atom's kind (0 for `1`, 1 for `cos`, 2 for
//! `sin`), the coefficient's numerator and denominator (signed), for `cos` and `sin` the
//! angle's length (its coefficients up to the last non-zero one) and its coefficients as
//! runs of one non-zero value: the number of runs, then for each the zeros before it, its
//! length and its value (signed; `q_3 + ... + q_9` is one run, not nine numbers, which made
//! the angles most of a long arm's data), the number of rate, acceleration and prismatic
//! displacement factors and for each `3 j` (`qd_j`), `3 j + 1` (`qdd_j`) or `3 j + 2` (`q_j`
//! of a prismatic joint) with its exponent, the number of run-time
//! parameters and for each its index in the derivation's name table with its exponent.
//! Numbers are written in digits of five bits, low first, with bit 5 set when more follow, as
//! the 64 printable characters of [`ALPHABET`] (no escapes in the literal); signed numbers
//! zigzag (0, -1, 1, -2 as 0, 1, 2, 3).

use crate::emit::EmitError;
use crate::expr::{Expr, Var};
use crate::ring::to_i128_pair;
use crate::slp::Emit;
use crate::trig::Trig;

/// An angle's coefficients as runs `(zeros before, length, value)` of one non-zero value.
fn runs(k: &[i32]) -> Vec<(usize, usize, i32)> {
    let mut out = Vec::new();
    let mut j = 0;
    while j < k.len() {
        let start = j;
        while j < k.len() && k[j] == 0 {
            j += 1;
        }
        if j == k.len() {
            break;
        }
        let zeros = j - start;
        let value = k[j];
        let first = j;
        while j < k.len() && k[j] == value {
            j += 1;
        }
        out.push((zeros, j - first, value));
    }
    out
}

/// The digits, in order of value.
pub const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

fn push(out: &mut Vec<u8>, mut v: u128) {
    loop {
        let low = (v & 31) as usize;
        v >>= 5;
        if v == 0 {
            out.push(ALPHABET[low]);
            return;
        }
        out.push(ALPHABET[low | 32]);
    }
}

#[allow(clippy::cast_sign_loss)]
fn push_signed(out: &mut Vec<u8>, v: i128) {
    push(out, ((v << 1) ^ (v >> 127)) as u128);
}

fn push_usize(out: &mut Vec<u8>, v: usize) {
    push(out, v as u128);
}

/// The encoding of `e`; the run-time parameters it names are added to `names` (their index
/// there is what the code stores).
///
/// # Errors
/// If a coefficient does not fit in `i128`.
pub fn encode<C: Emit>(e: &Expr<C>, names: &mut Vec<String>) -> Result<Vec<u8>, EmitError> {
    let mut out = Vec::new();
    for (m, t, coeff) in e.terms() {
        for (pm, c) in coeff.parts() {
            let (num, den) = to_i128_pair(&c).ok_or_else(|| EmitError {
                message: format!("exact coefficient {c} does not fit in i128"),
            })?;
            let (kind, angle) = match t {
                Trig::One => (0, &[][..]),
                Trig::Cos(a) => (1, a.coefficients()),
                Trig::Sin(a) => (2, a.coefficients()),
            };
            push_usize(&mut out, kind);
            push_signed(&mut out, num);
            push_signed(&mut out, den);
            if kind != 0 {
                push_usize(&mut out, angle.len());
                let runs = runs(angle);
                push_usize(&mut out, runs.len());
                for (zeros, length, k) in runs {
                    push_usize(&mut out, zeros);
                    push_usize(&mut out, length);
                    push_signed(&mut out, i128::from(k));
                }
            }
            let powers: Vec<(Var, u32)> = m.powers().collect();
            push_usize(&mut out, powers.len());
            for (v, e) in powers {
                let code = match v {
                    Var::Qd(j) => 3 * j,
                    Var::Qdd(j) => 3 * j + 1,
                    Var::Q(j) => 3 * j + 2,
                };
                push_usize(&mut out, code);
                push(&mut out, u128::from(e));
            }
            push_usize(&mut out, pm.powers().len());
            for (p, e) in pm.powers() {
                let k = match names.iter().position(|n| n == p.name()) {
                    Some(k) => k,
                    None => {
                        names.push(p.name().to_string());
                        names.len() - 1
                    }
                };
                push_usize(&mut out, k);
                push(&mut out, u128::from(*e));
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(code: &[u8], pos: &mut usize) -> u128 {
        let mut v = 0u128;
        let mut shift = 0;
        loop {
            let d = ALPHABET
                .iter()
                .position(|&c| c == code[*pos])
                .expect("a digit") as u128;
            *pos += 1;
            v |= (d & 31) << shift;
            shift += 5;
            if d & 32 == 0 {
                return v;
            }
        }
    }

    #[test]
    fn angles_are_runs() {
        assert_eq!(runs(&[1]), vec![(0, 1, 1)]);
        assert_eq!(runs(&[0, 0, 1, 1, 1]), vec![(2, 3, 1)]);
        assert_eq!(
            runs(&[0, 1, 1, 0, -1, 2, 2]),
            vec![(1, 2, 1), (1, 1, -1), (0, 2, 2)]
        );
    }

    #[test]
    fn numbers_round_trip_through_the_digits() {
        for v in [
            0u128,
            1,
            31,
            32,
            33,
            1023,
            1 << 40,
            u128::from(u64::MAX),
            u128::MAX,
        ] {
            let mut out = Vec::new();
            push(&mut out, v);
            assert!(out.iter().all(|c| ALPHABET.contains(c)));
            let mut pos = 0;
            assert_eq!(read(&out, &mut pos), v);
            assert_eq!(pos, out.len());
        }
        for v in [0i128, -1, 1, -2, 2, i128::MIN, i128::MAX, -123_456_789] {
            let mut out = Vec::new();
            push_signed(&mut out, v);
            let mut pos = 0;
            let z = read(&out, &mut pos);
            #[allow(clippy::cast_possible_wrap)]
            let back = ((z >> 1) as i128) ^ -((z & 1) as i128);
            assert_eq!(back, v);
        }
    }
}
