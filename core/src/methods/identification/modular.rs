//! Exact linear dependencies among the columns of a matrix known only through a sampler, by
//! elimination modulo primes and rational reconstruction.
//!
//! Elimination over the rationals on a spatial arm's regressor (a hundred rows of big
//! fractions) took 37 s of a user's unoptimised build for the PUMA 560. Modulo a prime below
//! 2^62 every entry is one machine word. For each prime the sampler fills the rows at fresh
//! random points; elimination in the caller's column order finds which columns are kept (the
//! first independent ones) and each other column's combination of them, modulo that prime.
//! The combinations are rational numbers independent of the prime and of the points, so the
//! Chinese remainder theorem joins their residues and rational reconstruction (the extended
//! Euclidean algorithm stopped half way) recovers each fraction once the primes' product
//! exceeds twice its numerator times its denominator. The result is accepted only when a
//! further prime, at further points, confirms both the kept columns and every combination.
//! A prime that divides some minor of the true matrix keeps fewer columns; it is skipped.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{One, Signed, ToPrimitive, Zero};

use crate::algebra::residue::{Prime, Residues};
use crate::algebra::ring::Rational;

/// A combination of kept columns: `(column, coefficient)` pairs.
type Combo<T> = Vec<(usize, T)>;
/// Each dependent column with its combination of kept columns.
pub type Dependent<T> = Vec<(usize, Combo<T>)>;
/// Columns modulo a prime, each with its index.
pub type Sampled = Vec<(usize, Vec<u64>)>;

/// The dependencies modulo one prime: the kept columns, and for each other column its
/// combination of them (`(column, [(kept column, coefficient)])`, `Y_k = sum beta Y_b`).
#[derive(Debug, PartialEq, Eq)]
struct Modular {
    kept: Vec<usize>,
    dependent: Dependent<u64>,
}

/// Elimination modulo `p` on `columns` (each with its index), taken in order.
fn eliminate_mod(p: Prime, columns: Sampled) -> Modular {
    // (pivot row, vector with 1 at the pivot, the vector as a combination of kept columns)
    let mut basis: Vec<(usize, Vec<u64>, Combo<u64>)> = Vec::new();
    let mut kept = Vec::new();
    let mut dependent = Vec::new();
    for (k, mut v) in columns {
        // v - sum a_i b_i, tracked as combo: v = Y_k - sum_j x_j Y_j.
        let mut combo: Vec<(usize, u64)> = Vec::new();
        for (pivot, b, bc) in &basis {
            let a = v[*pivot];
            if a == 0 {
                continue;
            }
            for (x, y) in v.iter_mut().zip(b) {
                *x = p.sub(*x, p.mul(a, *y));
            }
            for (j, x) in bc {
                let term = p.mul(a, *x);
                match combo.iter_mut().find(|(c, _)| c == j) {
                    Some(e) => e.1 = p.add(e.1, term),
                    None => combo.push((*j, term)),
                }
            }
        }
        match v.iter().position(|x| *x != 0) {
            None => {
                combo.retain(|(_, x)| *x != 0);
                combo.sort_by_key(|e| e.0);
                dependent.push((k, combo));
            }
            Some(pivot) => {
                let inv = p.inv(v[pivot]).unwrap_or(0);
                let v = v.into_iter().map(|x| p.mul(x, inv)).collect();
                // The normalised vector is (Y_k - combo) / v_pivot.
                let mut bc: Vec<(usize, u64)> = vec![(k, inv)];
                bc.extend(combo.into_iter().map(|(j, x)| (j, p.neg(p.mul(x, inv)))));
                basis.push((pivot, v, bc));
                kept.push(k);
            }
        }
    }
    Modular { kept, dependent }
}

/// `x mod m` as a fraction `n / d` with `|n|, d <= sqrt(m / 2)`, if there is one.
fn reconstruct(x: &BigInt, m: &BigInt) -> Option<Rational> {
    let bound = (m / BigInt::from(2)).sqrt();
    let (mut r0, mut r1) = (m.clone(), x.mod_floor(m));
    let (mut t0, mut t1) = (BigInt::zero(), BigInt::one());
    while r1 > bound {
        let q = &r0 / &r1;
        let r2 = &r0 - &q * &r1;
        let t2 = &t0 - &q * &t1;
        (r0, r1, t0, t1) = (r1, r2, t1, t2);
    }
    (t1.abs() <= bound && !t1.is_zero() && r1.gcd(&t1).is_one()).then(|| Rational::new(r1, t1))
}

/// Exact dependencies among the columns of a matrix: `sample(p, residues)` returns its columns
/// modulo `p` at fresh points (the same number of rows for every column, more rows than
/// independent columns), in the order elimination should take them. The kept columns (the
/// first independent ones, in that order), and for each kept column the other columns it
/// absorbs with their exact coefficients: column `j = sum_b beta_jb column_b` gives base
/// parameter `b` the term `beta_jb theta_j`. `None` if a dozen primes do not settle it.
pub fn dependencies(
    sample: &mut dyn FnMut(Prime, &mut Residues) -> Option<Sampled>,
) -> Option<(Vec<usize>, Dependent<Rational>)> {
    let mut residues = Residues(0x5EED_0FA2_A5A5);
    let mut reference: Option<(Prime, Modular)> = None;
    // Per dependent column, per kept column: the residue so far, modulo `modulus`.
    let mut joined: Vec<Vec<BigInt>> = Vec::new();
    let mut modulus = BigInt::one();
    let mut candidate: Option<Dependent<Rational>> = None;
    for p in Prime::descending().take(12) {
        let m = eliminate_mod(p, sample(p, &mut residues)?);
        let Some((first_prime, r)) = &reference else {
            reference = Some((p, m));
            continue;
        };
        if m.kept.len() < r.kept.len() {
            // An unlucky prime: it divides a minor of the matrix.
            continue;
        }
        if m.kept != r.kept || m.dependent.len() != r.dependent.len() {
            // The reference prime (or its points) was the unlucky one: start again from this.
            (reference, joined, modulus, candidate) =
                (Some((p, m)), Vec::new(), BigInt::one(), None);
            continue;
        }
        if let Some(c) = &candidate {
            if confirms(p, c, &m) {
                return Some((m.kept, c.clone()));
            }
        }
        let first = joined.is_empty();
        if first {
            // Fold in the reference prime's residues first.
            joined = dense(r)
                .into_iter()
                .map(|row| row.into_iter().map(BigInt::from).collect())
                .collect();
            modulus = BigInt::from(first_prime.0);
        }
        let next = dense(&m);
        let pb = BigInt::from(p.0);
        for (row, new_row) in joined.iter_mut().zip(&next) {
            for (x, y) in row.iter_mut().zip(new_row) {
                // x + modulus * ((y - x) / modulus mod p)
                let x_mod = x.mod_floor(&pb).to_u64().unwrap_or(0);
                let inv = p
                    .inv(modulus.mod_floor(&pb).to_u64().unwrap_or(0))
                    .unwrap_or(0);
                let t = p.mul(p.sub(*y, x_mod), inv);
                *x += &modulus * BigInt::from(t);
            }
        }
        modulus *= &pb;
        candidate = rationals(r, &joined, &modulus);
    }
    None
}

/// The combinations as a dense table: per dependent column, per kept column.
fn dense(m: &Modular) -> Vec<Vec<u64>> {
    m.dependent
        .iter()
        .map(|(_, combo)| {
            m.kept
                .iter()
                .map(|b| combo.iter().find(|(c, _)| c == b).map_or(0, |e| e.1))
                .collect()
        })
        .collect()
}

/// Every residue reconstructed as a fraction, or `None` if one is not yet.
fn rationals(
    shape: &Modular,
    joined: &[Vec<BigInt>],
    modulus: &BigInt,
) -> Option<Dependent<Rational>> {
    shape
        .dependent
        .iter()
        .zip(joined)
        .map(|((k, _), row)| {
            let combo = shape
                .kept
                .iter()
                .zip(row)
                .filter(|(_, x)| !x.is_zero())
                .map(|(b, x)| Some((*b, reconstruct(x, modulus)?)))
                .collect::<Option<Vec<_>>>()?;
            Some((*k, combo))
        })
        .collect()
}

/// Whether the fractions reduce to the combinations found modulo `p`.
fn confirms(p: Prime, candidate: &[(usize, Combo<Rational>)], m: &Modular) -> bool {
    candidate
        .iter()
        .zip(&m.dependent)
        .all(|((k, combo), (k2, found))| {
            let reduced: Option<Vec<(usize, u64)>> = combo
                .iter()
                .map(|(b, r)| Some((*b, p.of(r)?)))
                .filter(|e| e.as_ref().is_none_or(|(_, x)| *x != 0))
                .collect();
            reduced.is_some_and(|mut reduced| {
                reduced.sort_by_key(|e| e.0);
                k == k2 && reduced == *found
            })
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::ring::ratio;

    #[test]
    fn fractions_come_back() {
        let m = BigInt::from(Prime::descending().next().unwrap().0);
        let p = Prime(m.to_u64().unwrap());
        for r in [ratio(9, 16), ratio(-4_661_281, 25_000_000), ratio(3, 1)] {
            let x = BigInt::from(p.of(&r).unwrap());
            assert_eq!(reconstruct(&x, &m), Some(r));
        }
    }

    #[test]
    fn dependencies_of_a_known_matrix() {
        // Columns a, b, c = 2/3 a - 5/7 b, d = 0, e: sampled as random combinations.
        let mut sample = |p: Prime, r: &mut Residues| {
            let rows = 6;
            let a: Vec<u64> = (0..rows).map(|_| r.next(p)).collect();
            let b: Vec<u64> = (0..rows).map(|_| r.next(p)).collect();
            let e: Vec<u64> = (0..rows).map(|_| r.next(p)).collect();
            let (x, y) = (p.of(&ratio(2, 3))?, p.of(&ratio(-5, 7))?);
            let c = a
                .iter()
                .zip(&b)
                .map(|(u, v)| p.add(p.mul(x, *u), p.mul(y, *v)))
                .collect();
            Some(vec![(0, a), (1, b), (2, c), (3, vec![0; rows]), (4, e)])
        };
        let (kept, dependent) = dependencies(&mut sample).unwrap();
        assert_eq!(kept, vec![0, 1, 4]);
        assert_eq!(
            dependent,
            vec![(2, vec![(0, ratio(2, 3)), (1, ratio(-5, 7))]), (3, vec![])]
        );
    }
}
