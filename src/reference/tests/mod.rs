//! Cross-checks of the reference algorithms against each other, against closed forms worked
//! out by hand and against the energies, and the support they share: a deterministic random
//! arm generator and tolerant comparisons.

use super::*;
use crate::{Link, Model, Payload};
use nalgebra::{Point2, SMatrix, SVector, Vector2 as V2, Vector3};

mod cross_checks;
mod edge_cases;
mod revolute;
mod trajectories;

/// SplitMix64: a tiny deterministic PRNG.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in `[lo, hi)`.
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        #[allow(clippy::cast_precision_loss)]
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        lo + (hi - lo) * unit
    }

    /// `value()` with probability 3/4, else zero: the zero special case stays covered.
    fn often(&mut self, value: impl FnOnce(&mut Self) -> f64) -> f64 {
        if self.uniform(0.0, 1.0) < 0.75 {
            value(self)
        } else {
            0.0
        }
    }

    fn links<const N: usize>(&mut self) -> [Link; N] {
        core::array::from_fn(|_| {
            let length = self.uniform(0.2, 2.0);
            let mass = self.uniform(0.1, 5.0);
            Link {
                length,
                mass,
                inertia: mass * length * length * self.uniform(0.01, 0.2),
                // Anywhere along the link, sometimes a little beyond either end, and off
                // the link's axis to either side.
                com: V2::new(
                    length * self.uniform(-0.2, 1.2),
                    length * self.uniform(-0.3, 0.3),
                ),
                armature: self.often(|r| r.uniform(0.0, 0.5)),
                damping: self.often(|r| r.uniform(0.0, 2.0)),
                frictionloss: self.often(|r| r.uniform(0.0, 1.0)),
                joint: crate::Joint::Revolute,
                range: None,
            }
        })
    }

    fn payload(&mut self) -> Payload {
        if self.uniform(0.0, 1.0) < 0.25 {
            return Payload::NONE;
        }
        Payload {
            mass: self.uniform(0.0, 3.0),
            inertia: self.uniform(0.0, 0.2),
            com: V2::new(self.uniform(-0.3, 0.3), self.uniform(-0.3, 0.3)),
        }
    }

    fn model<const N: usize>(&mut self) -> Model<N> {
        let gravity = self.uniform(0.0, 15.0);
        Model::new(self.links(), gravity).with_payload(self.payload())
    }

    fn vector<const N: usize>(&mut self, bound: f64) -> SVector<f64, N> {
        SVector::from_fn(|_, _| self.uniform(-bound, bound))
    }
}

/// `|a - b| <= tol * max(1, |a|, |b|)` element-wise, on the max-norm scale of the operands.
#[track_caller]
fn assert_close<const R: usize, const C: usize>(
    a: &SMatrix<f64, R, C>,
    b: &SMatrix<f64, R, C>,
    tol: f64,
    what: &str,
) {
    let scale = 1.0_f64.max(a.amax()).max(b.amax());
    let err = (a - b).amax();
    assert!(
        err <= tol * scale,
        "{what}: error {err:e} exceeds {tol:e} * {scale}\n  a = {a}\n  b = {b}"
    );
}

#[track_caller]
fn assert_close_f(a: f64, b: f64, tol: f64, what: &str) {
    let scale = 1.0_f64.max(a.abs()).max(b.abs());
    assert!(
        (a - b).abs() <= tol * scale,
        "{what}: {a} vs {b} (error {:e})",
        (a - b).abs()
    );
}

/// `value` times the j-th standard basis vector.
fn basis<const N: usize>(j: usize, value: f64) -> SVector<f64, N> {
    SVector::from_fn(|i, _| if i == j { value } else { 0.0 })
}
