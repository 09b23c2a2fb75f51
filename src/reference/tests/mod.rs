//! Cross-checks of the reference algorithms against each other, against closed forms worked
//! out by hand and against the energies, and the support they share: a deterministic random
//! arm generator and tolerant comparisons.

use super::*;
use crate::{Joint, Link, Model, Payload};
use nalgebra::{Point2, SMatrix, SVector, Vector2 as V2, Vector3};

mod cross_checks;
mod edge_cases;
mod prismatic;
mod regressors;
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
                stiffness: 0.0,
                springref: 0.0,
                joint: Joint::Revolute,
                range: None,
                offset: 0.0,
                reversed: false,
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

    /// [`model`](Self::model) with each joint revolute or prismatic, evenly.
    fn mixed_model<const N: usize>(&mut self) -> Model<N> {
        let mut model = self.model();
        for link in &mut model.links {
            link.joint = if self.uniform(0.0, 1.0) < 0.5 {
                Joint::Prismatic
            } else {
                Joint::Revolute
            };
        }
        model
    }

    fn vector<const N: usize>(&mut self, bound: f64) -> SVector<f64, N> {
        SVector::from_fn(|_, _| self.uniform(-bound, bound))
    }

    /// A configuration of `model`: revolute angles in `[-bound, bound)`, prismatic slides in
    /// `[-0.5, 1.0)` m (a negative slide pulls a link back over the one before it).
    fn configuration<const N: usize>(&mut self, model: &Model<N>, bound: f64) -> SVector<f64, N> {
        SVector::from_fn(|i, _| {
            if slides(&model.links[i]) {
                self.uniform(-0.5, 1.0)
            } else {
                self.uniform(-bound, bound)
            }
        })
    }
}

/// The largest relative error each named check measured in one test, printed at its end (run
/// with `--nocapture` to see them).
#[derive(Default)]
struct Worst(std::collections::BTreeMap<&'static str, f64>);

impl Worst {
    #[track_caller]
    fn close<const R: usize, const C: usize>(
        &mut self,
        a: &SMatrix<f64, R, C>,
        b: &SMatrix<f64, R, C>,
        tol: f64,
        what: &'static str,
    ) {
        self.note(what, assert_close(a, b, tol, what));
    }

    #[track_caller]
    fn close_f(&mut self, a: f64, b: f64, tol: f64, what: &'static str) {
        self.note(what, assert_close_f(a, b, tol, what));
    }

    fn note(&mut self, what: &'static str, err: f64) {
        let worst = self.0.entry(what).or_insert(0.0);
        *worst = worst.max(err);
    }

    fn print(&self, test: &str) {
        for (what, err) in &self.0 {
            std::println!("{test}: {what}: {err:.1e}");
        }
    }
}

/// `|a - b| <= tol * max(1, |a|, |b|)` element-wise, on the max-norm scale of the operands;
/// returns the error relative to that scale.
#[track_caller]
fn assert_close<const R: usize, const C: usize>(
    a: &SMatrix<f64, R, C>,
    b: &SMatrix<f64, R, C>,
    tol: f64,
    what: &str,
) -> f64 {
    let scale = 1.0_f64.max(a.amax()).max(b.amax());
    let err = (a - b).amax();
    assert!(
        err <= tol * scale,
        "{what}: error {err:e} exceeds {tol:e} * {scale}\n  a = {a}\n  b = {b}"
    );
    err / scale
}

/// [`assert_close`] for numbers.
#[track_caller]
fn assert_close_f(a: f64, b: f64, tol: f64, what: &str) -> f64 {
    let scale = 1.0_f64.max(a.abs()).max(b.abs());
    assert!(
        (a - b).abs() <= tol * scale,
        "{what}: {a} vs {b} (error {:e})",
        (a - b).abs()
    );
    (a - b).abs() / scale
}

/// The fourth-order central difference of `f` at 0 with step `h`: truncation
/// `h^4 f^(5) / 30`, rounding about `eps |f| / h`.
fn derivative<const R: usize, const C: usize>(
    f: impl Fn(f64) -> SMatrix<f64, R, C>,
    h: f64,
) -> SMatrix<f64, R, C> {
    (f(-2.0 * h) - f(-h) * 8.0 + f(h) * 8.0 - f(2.0 * h)) / (12.0 * h)
}

/// `value` times the j-th standard basis vector.
fn basis<const N: usize>(j: usize, value: f64) -> SVector<f64, N> {
    SVector::from_fn(|i, _| if i == j { value } else { 0.0 })
}
