//! What the identification examples share: a deterministic random source, Swevers' periodic
//! excitation, the base regressor stacked over a run, and least squares with each parameter's
//! standard deviation.

use std::error::Error;
use std::f64::consts::TAU;

use planar_arm::nalgebra::{DMatrix, DVector, SVector};
use planar_arm::Identification;

use super::num::fixed;

/// Deterministic splitmix64 numbers, uniform and (Box-Muller) Gaussian.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        #[allow(clippy::cast_precision_loss)]
        let u = (z >> 11) as f64 / (1u64 << 53) as f64;
        u
    }

    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    pub fn gaussian(&mut self) -> f64 {
        // 1 - u lies in (0, 1], so the logarithm is finite.
        let (u, v) = (1.0 - self.next(), self.next());
        (-2.0 * u.ln()).sqrt() * (TAU * v).cos()
    }

    pub fn noise<const N: usize>(&mut self, sigma: &SVector<f64, N>) -> SVector<f64, N> {
        SVector::from_fn(|j, _| sigma[j] * self.gaussian())
    }
}

/// Fundamental frequency of the excitation, Hz: a 10 s period.
pub const BASE_HZ: f64 = 0.1;
pub const HARMONICS: usize = 5;

/// How far an excitation may take each joint from its centre: angle (rad), speed (rad/s) and
/// acceleration (rad/s^2), so that the arm sweeps its range while the motors stay within their
/// speed and torque.
#[derive(Clone, Copy)]
pub struct Bounds<const N: usize> {
    pub swing: [f64; N],
    pub speed: [f64; N],
    pub acceleration: [f64; N],
}

/// Swevers' periodic excitation: per joint
/// `q(t) = q0 + sum_l a_l / (w l) sin(w l t) - b_l / (w l) cos(w l t)`, `w = 2 pi 0.1 Hz`.
pub struct Excitation<const N: usize> {
    q0: [f64; N],
    a: [[f64; HARMONICS]; N],
    b: [[f64; HARMONICS]; N],
}

impl<const N: usize> Excitation<N> {
    pub fn random(rng: &mut Rng, q0: [f64; N], bounds: &Bounds<N>) -> Self {
        let mut coefficients =
            || std::array::from_fn(|_| std::array::from_fn(|_| rng.uniform(-1.0, 1.0)));
        let mut e = Self {
            q0,
            a: coefficients(),
            b: coefficients(),
        };
        // Scale each joint's series so that its largest swing, speed or acceleration over a
        // period meets its bound.
        let mut peak = [0.0_f64; N];
        for k in 0..1000 {
            let (q, qd, qdd) = e.state(f64::from(k) / (1000.0 * BASE_HZ));
            for j in 0..N {
                let ratio = ((q[j] - q0[j]).abs() / bounds.swing[j])
                    .max(qd[j].abs() / bounds.speed[j])
                    .max(qdd[j].abs() / bounds.acceleration[j]);
                peak[j] = peak[j].max(ratio);
            }
        }
        for ((a, b), p) in e.a.iter_mut().zip(&mut e.b).zip(peak) {
            for (a, b) in a.iter_mut().zip(b.iter_mut()) {
                *a /= p;
                *b /= p;
            }
        }
        e
    }

    /// `q, qd, qdd` at time `t`, analytic.
    pub fn state(&self, t: f64) -> (SVector<f64, N>, SVector<f64, N>, SVector<f64, N>) {
        let omega = TAU * BASE_HZ;
        let mut q = SVector::from(self.q0);
        let (mut qd, mut qdd) = (SVector::zeros(), SVector::zeros());
        for j in 0..N {
            // The l-th harmonic's frequency, omega l.
            let mut wl = 0.0;
            for (&a, &b) in self.a[j].iter().zip(&self.b[j]) {
                wl += omega;
                let (s, c) = (wl * t).sin_cos();
                q[j] += (a * s - b * c) / wl;
                qd[j] += a * c + b * s;
                qdd[j] += wl * (b * c - a * s);
            }
        }
        (q, qd, qdd)
    }

    /// The excitation among `candidates` random ones whose column-scaled base regressor
    /// (sampled coarsely over one period) is best conditioned; returns it and the best and
    /// worst numbers.
    pub fn best<A, const P: usize, const B: usize>(
        arm: &A,
        rng: &mut Rng,
        candidates: u32,
        q0: [f64; N],
        bounds: &Bounds<N>,
    ) -> (Self, f64, f64)
    where
        A: Identification<N, P, B>,
    {
        let mut best: Option<(Self, f64)> = None;
        let mut worst = 0.0_f64;
        for _ in 0..candidates {
            let e = Self::random(rng, q0, bounds);
            let states: Vec<_> = (0..200)
                .map(|k| e.state(f64::from(k) / (200.0 * BASE_HZ)))
                .collect();
            let c = condition(&scale_columns(&stack(arm, &states)));
            worst = worst.max(c);
            if best.as_ref().is_none_or(|(_, b)| c < *b) {
                best = Some((e, c));
            }
        }
        let (e, c) = best.expect("at least one candidate");
        (e, c, worst)
    }
}

/// A state `(q, qd, qdd)`.
pub type State<const N: usize> = (SVector<f64, N>, SVector<f64, N>, SVector<f64, N>);

/// The base regressor stacked over the states, `N` rows per state.
pub fn stack<A, const N: usize, const P: usize, const B: usize>(
    arm: &A,
    states: &[State<N>],
) -> DMatrix<f64>
where
    A: Identification<N, P, B>,
{
    let mut w = DMatrix::zeros(N * states.len(), B);
    for (k, (q, qd, qdd)) in states.iter().enumerate() {
        w.fixed_view_mut::<N, B>(N * k, 0)
            .copy_from(&arm.base_regressor(q, qd, qdd));
    }
    w
}

/// Divides each column by its norm: the condition number then no longer depends on units.
pub fn scale_columns(w: &DMatrix<f64>) -> DMatrix<f64> {
    let mut s = w.clone();
    for mut c in s.column_iter_mut() {
        let n = c.norm();
        c /= n;
    }
    s
}

pub fn condition(w: &DMatrix<f64>) -> f64 {
    let s = w.singular_values();
    s.max() / s.min()
}

/// A least-squares estimate with its covariance.
pub struct Estimate<const B: usize> {
    pub theta: SVector<f64, B>,
    pub std: SVector<f64, B>,
    pub sigma: f64,
    pub condition: f64,
    pub scaled_condition: f64,
}

/// Least squares `W theta = tau` by SVD, each row weighted by `1 / weights[row % N]` (the
/// joints' noise levels, or ones); the noise level is estimated from the weighted residual,
/// as on a real robot, and the covariance is `sigma^2 (W^T W)^-1 = sigma^2 V S^-2 V^T`.
pub fn least_squares<const N: usize, const B: usize>(
    w: &DMatrix<f64>,
    tau: &[SVector<f64, N>],
    weights: &SVector<f64, N>,
) -> Result<Estimate<B>, Box<dyn Error>> {
    let mut w = w.clone();
    for (r, mut row) in w.row_iter_mut().enumerate() {
        row /= weights[r % N];
    }
    let tau = DVector::from_iterator(
        w.nrows(),
        tau.iter()
            .flat_map(|t| t.iter().zip(weights.iter()).map(|(x, s)| x / s)),
    );
    let scaled_condition = condition(&scale_columns(&w));
    let svd = w.clone().svd(true, true);
    let condition = svd.singular_values.max() / svd.singular_values.min();
    let theta = svd.solve(&tau, 0.0)?;
    let residual = &tau - &w * &theta;
    let theta = SVector::from_column_slice(theta.as_slice());
    #[allow(clippy::cast_precision_loss)]
    let dof = (w.nrows() - B) as f64;
    let sigma = (residual.norm_squared() / dof).sqrt();
    let v_t = svd.v_t.as_ref().ok_or("no V")?;
    let std = SVector::from_fn(|i, _| {
        let var: f64 = (0..B)
            .map(|k| (v_t[(k, i)] / svd.singular_values[k]).powi(2))
            .sum();
        sigma * var.sqrt()
    });
    Ok(Estimate {
        theta,
        std,
        sigma,
        condition,
        scaled_condition,
    })
}

pub fn rms(values: impl Iterator<Item = f64>) -> f64 {
    let (mut sum, mut n) = (0.0, 0.0);
    for v in values {
        sum += v * v;
        n += 1.0;
    }
    (sum / n).sqrt()
}

/// Prints the table of base parameters and returns the largest error in standard deviations.
pub fn print_estimate<const B: usize>(
    names: &[&str],
    truth: &SVector<f64, B>,
    est: &Estimate<B>,
) -> f64 {
    let width = names.iter().map(|n| n.len()).max().unwrap_or(0).min(60);
    println!(
        "{:width$}  {:>10} {:>10} {:>10} {:>9} {:>7}",
        "base parameter", "true", "identified", "error", "std dev", "err/std"
    );
    let mut worst = 0.0_f64;
    for i in 0..B {
        let err = est.theta[i] - truth[i];
        let z = err / est.std[i];
        worst = worst.max(z.abs());
        let name = if names[i].len() > width {
            format!("{}...", &names[i][..width - 3])
        } else {
            names[i].to_string()
        };
        println!(
            "{name:width$}  {:>10} {:>10} {:>10} {:>9} {:>7}",
            fixed(truth[i], 5),
            fixed(est.theta[i], 5),
            fixed(err, 5),
            fixed(est.std[i], 5),
            fixed(z, 2)
        );
    }
    println!("largest error: {worst:.2} standard deviations");
    worst
}
