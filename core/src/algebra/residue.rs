//! Arithmetic modulo a prime below 2^62, one machine word per residue: what exact linear
//! algebra on large rational matrices costs least in (see
//! `methods::identification::modular`).

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::ToPrimitive;

use super::ring::Rational;

/// A prime below 2^62: sums of two residues fit in a `u64`, products in a `u128`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Prime(pub u64);

impl Prime {
    /// `a b mod p`.
    #[must_use]
    pub fn mul(self, a: u64, b: u64) -> u64 {
        u64::try_from((u128::from(a) * u128::from(b)) % u128::from(self.0)).unwrap_or(0)
    }
    /// `a + b mod p`.
    #[must_use]
    pub fn add(self, a: u64, b: u64) -> u64 {
        let s = a + b;
        if s >= self.0 {
            s - self.0
        } else {
            s
        }
    }
    /// `a - b mod p`.
    #[must_use]
    pub fn sub(self, a: u64, b: u64) -> u64 {
        if a >= b {
            a - b
        } else {
            a + self.0 - b
        }
    }
    /// `-a mod p`.
    #[must_use]
    pub fn neg(self, a: u64) -> u64 {
        if a == 0 {
            0
        } else {
            self.0 - a
        }
    }
    fn pow(self, mut a: u64, mut e: u64) -> u64 {
        let mut r = 1;
        while e > 0 {
            if e & 1 == 1 {
                r = self.mul(r, a);
            }
            a = self.mul(a, a);
            e >>= 1;
        }
        r
    }
    /// `1 / a mod p`; `None` for zero.
    #[must_use]
    pub fn inv(self, a: u64) -> Option<u64> {
        (a != 0).then(|| self.pow(a, self.0 - 2))
    }
    /// A rational's residue; `None` when the prime divides its denominator.
    #[must_use]
    pub fn of(self, r: &Rational) -> Option<u64> {
        let p = BigInt::from(self.0);
        let residue = |x: &BigInt| x.mod_floor(&p).to_u64().unwrap_or(0);
        self.inv(residue(r.denom()))
            .map(|d| self.mul(residue(r.numer()), d))
    }

    /// Whether `n` is prime: Miller-Rabin with the first twelve primes as bases, exact for
    /// every `n < 3.3e24`.
    fn is_prime(n: u64) -> bool {
        const BASES: [u64; 12] = [2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37];
        if n < 2 {
            return false;
        }
        if let Some(&b) = BASES.iter().find(|&&b| n.is_multiple_of(b)) {
            return n == b;
        }
        let field = Self(n);
        let (mut d, mut s) = (n - 1, 0);
        while d % 2 == 0 {
            d /= 2;
            s += 1;
        }
        BASES.iter().all(|&a| {
            let mut x = field.pow(a, d);
            if x == 1 || x == n - 1 {
                return true;
            }
            for _ in 1..s {
                x = field.mul(x, x);
                if x == n - 1 {
                    return true;
                }
            }
            false
        })
    }

    /// The primes below 2^62, largest first.
    pub fn descending() -> impl Iterator<Item = Self> {
        (0..(1u64 << 62))
            .rev()
            .step_by(2)
            .filter(|&n| Self::is_prime(n))
            .map(Self)
    }
}

/// Deterministic residues: a 64-bit linear congruential generator (Knuth's MMIX constants),
/// so that the same input always derives the same output.
pub struct Residues(pub u64);

impl Residues {
    /// A residue modulo `p`.
    pub fn next(&mut self, p: Prime) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 2) % p.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::ring::ratio;

    #[test]
    fn primes_are_found() {
        let largest = Prime::descending().next().map(|p| p.0);
        assert_eq!(largest, Some((1 << 62) - 57));
        assert!(Prime::is_prime((1 << 61) - 1));
        assert!(!Prime::is_prime((1 << 61) + 1));
        assert!(!Prime::is_prime(3_215_031_751)); // a strong pseudoprime to bases 2, 3, 5, 7
        assert!(Prime::descending().take(5).all(|p| Prime::is_prime(p.0)));
    }

    #[test]
    fn residues_of_fractions() {
        let p = Prime(1_000_000_007);
        let x = p.of(&ratio(3, 4)).unwrap();
        assert_eq!(p.mul(x, 4), 3);
        assert_eq!(p.of(&ratio(1, 1_000_000_007)), None);
        assert_eq!(p.mul(p.inv(x).unwrap(), x), 1);
    }
}
