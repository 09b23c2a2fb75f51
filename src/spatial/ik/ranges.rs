//! Keeping the solutions within the joints' ranges: each angle as its representative in the
//! range (in (-pi, pi] for a free joint), the solutions no range admits dropped.

use nalgebra::SVector;

use super::IkSolutions;
use crate::kinematics::range::fit;
use crate::{ArmError, Joint};

/// The solutions of `all` within `ranges`, angles wrapped; `slack` is how far (metres) a slide
/// may overrun its range and be clamped onto it. `Err(BeyondJointRange)` for the solution
/// nearest its ranges when `all` has solutions and none fits.
pub(crate) fn keep_within<const N: usize>(
    all: &IkSolutions<N>,
    kinds: &[Joint; N],
    ranges: &[Option<(f64, f64)>; N],
    slack: f64,
) -> Result<IkSolutions<N>, ArmError> {
    let mut kept = IkSolutions::new();
    if all.singular() {
        kept.mark_singular();
    }
    let mut nearest: Option<(usize, f64)> = None;
    for q in all.iter() {
        let mut out = SVector::<f64, N>::zeros();
        let mut worst: Option<(usize, f64)> = None;
        for i in 0..N {
            let value = match kinds[i] {
                Joint::Revolute => crate::kinematics::wrap(q[i]),
                Joint::Prismatic => q[i],
            };
            match fit(kinds[i], value, ranges[i], slack) {
                Ok(v) => out[i] = v,
                Err(e) if worst.is_none_or(|(_, w)| e > w) => worst = Some((i, e)),
                Err(_) => {}
            }
        }
        match worst {
            None => kept.push(out),
            Some((i, e)) if nearest.is_none_or(|(_, n)| e < n) => nearest = Some((i, e)),
            Some(_) => {}
        }
    }
    match nearest {
        Some((joint, excess)) if kept.is_empty() => Err(ArmError::BeyondJointRange {
            joint,
            kind: kinds[joint],
            excess,
        }),
        _ => Ok(kept),
    }
}
