//! The Riccati equations written out, for checking `lqr` and `dlqr` with nothing of theirs.

use planar_arm::nalgebra::SMatrix;

/// The continuous Riccati residual written out, relative to the size of its terms (the
/// quadratic term can be far larger than `P`, and the terms cancel).
pub fn care_residual<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    q: &SMatrix<f64, S, S>,
    r: &SMatrix<f64, M, M>,
    p: &SMatrix<f64, S, S>,
) -> f64 {
    let r_inverse = r.try_inverse().unwrap();
    let (pa, pgp) = (p * a, p * b * r_inverse * b.transpose() * p);
    let res = pa.transpose() + pa - pgp + q;
    res.amax() / (pa.amax() + pgp.amax() + q.amax())
}

/// The discrete Riccati residual written out, relative to the size of its terms.
pub fn dare_residual<const S: usize, const M: usize>(
    a: &SMatrix<f64, S, S>,
    b: &SMatrix<f64, S, M>,
    q: &SMatrix<f64, S, S>,
    r: &SMatrix<f64, M, M>,
    p: &SMatrix<f64, S, S>,
) -> f64 {
    let inner = (r + b.transpose() * p * b).try_inverse().unwrap();
    let apa = a.transpose() * p * a;
    let correction = a.transpose() * p * b * inner * b.transpose() * p * a;
    let res = apa - correction + q - p;
    res.amax() / (apa.amax() + correction.amax() + q.amax() + p.amax())
}
