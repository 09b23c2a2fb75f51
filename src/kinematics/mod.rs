//! Inverse kinematics, inverse statics, work-spaces, manipulability and a damped-least-squares
//! solver for planar serial arms.
//!
//! The closed forms follow B. K. P. Horn, *Kinematics, Statics, and Dynamics of Two-D
//! Manipulators* (MIT AI working paper), re-derived, with these corrections to the printed text:
//!
//! - three-link inverse kinematics: the paper prints `theta3 = -theta2 - theta1`; the last angle
//!   is `q3 = phi - q1 - q2`, where `phi` is the orientation of the last link;
//! - usable (dexterous) work-space: the paper gives the central disk the radius
//!   `l3 - |l1 - l2|`; it is `min(l3 - |l1 - l2|, l1 + l2 - l3)`, and the annulus
//!   `l3 + |l1 - l2| ..= l1 + l2 - l3` exists exactly when `l3 <= min(l1, l2)` (its width is
//!   `2 (min(l1, l2) - l3)`), whether or not `l3 < |l1 - l2|`.
//!
//! The paper's inverse statics (the two-link `u`, `v` and the three-link 3 x 3 inverse with
//! determinant `l1 l2 sin q2`) are correct as printed; this module evaluates them in an
//! algebraically equal form that needs no product of lengths.
//!
//! Conventions: `q[0]` is link 1's angle from +x, `q[i]` (i > 0) is link i+1's angle relative
//! to link i, all zeros is the arm stretched along +x, joint 1 is at the origin and the tip is
//! at the end of the last link. Angles returned by the closed forms lie in (-pi, pi] unless a
//! joint range asks for another turn.
//!
//! A prismatic joint ([`Joint::Prismatic`](crate::Joint)) slides its link along the previous
//! link's direction (for the first link, +x of the base) by `q[i]` metres without turning it;
//! its generalised force is a force, in newtons. The functions named for lengths
//! ([`ik2`], [`ik3`], [`inverse_statics`], [`reachable_target`], [`Workspace::of_lengths`],
//! [`DexterousWorkspace`]) are for revolute links; those that take links
//! ([`tip_pose_of`], [`jacobian_of`], [`inverse_statics_of`], [`reachable_target_of`],
//! [`inverse_kinematics_of`], [`Workspace::of_links`], [`sample_tips`]) take any mix of joints
//! and their ranges, and the closed forms [`ik_rp`], [`ik_pr`] and [`ik_prr`] the arms with a
//! prismatic joint they are named for.
//!
//! Nothing here panics or returns NaN. The fallible functions answer NaN or infinite
//! arguments with [`ArmError::NonFinite`]; the infallible ones document what they make of
//! them. Lengths are used with their signs (a link of negative length is the positive one
//! turned by pi); the derive macro only passes positive ones.

mod chain;
mod closed_form;
mod dyn_arm;
mod manipulability;
pub(crate) mod numeric;
mod prismatic;
pub(crate) mod range;
mod skeleton;
mod statics;
#[cfg(test)]
mod test_support;
mod workspace;

pub use chain::{jacobian_of, sample_tips, tip_pose_of, TipSamples};
pub use closed_form::{
    ik2, ik2_equal, ik2_in_ranges, ik3, ik3_in_ranges, ik3_position, ClosedFormIk,
};
pub use dyn_arm::DynArm;
pub use manipulability::{is_singular, manipulability};
pub use numeric::{
    inverse_kinematics_near, inverse_kinematics_of, reachable_target, reachable_target_of,
    solve_dls, DlsOptions, IkTarget, DLS_MAX_STEP,
};
pub use prismatic::{ik_pr, ik_prr, ik_rp};
pub use skeleton::Skeleton;
pub use statics::{
    inverse_statics, inverse_statics_of, tip_force2, tip_wrench3, InverseStatics,
    RedundantTipWrench, StaticWrench, TipForce, TipWrench, SINGULAR_THRESHOLD,
    UNBALANCED_TOLERANCE,
};
pub use workspace::{DexterousWorkspace, DexterousWorkspaceExt, Workspace};

use core::f64::consts::{PI, TAU};

use nalgebra::SVector;

use crate::ArmError;

/// Relative tolerance on reach: a target whose distance from the base lies outside the
/// reachable annulus by at most `REACH_TOLERANCE * outer_radius` counts as lying on the
/// boundary (the law-of-cosines term is clamped into `[-1, 1]`); farther out it is
/// [`ArmError::Unreachable`]. [`Workspace::contains`] and [`DexterousWorkspace::contains`]
/// use the same slack, so they agree with the inverse kinematics.
pub const REACH_TOLERANCE: f64 = 1e-9;

/// Wraps an angle into (-pi, pi]; NaN and infinities come back as they are.
#[inline]
pub(crate) fn wrap(a: f64) -> f64 {
    if a.is_finite() {
        wrap_angle(a)
    } else {
        a
    }
}

/// Wraps an angle into (-pi, pi]. `a` must be finite.
#[inline]
fn wrap_angle(a: f64) -> f64 {
    if a > -PI && a <= PI {
        a
    } else {
        let r = turn_angle(a);
        if r > PI {
            r - TAU
        } else {
            r
        }
    }
}

/// An angle in [0, 2 pi): `a.rem_euclid(TAU)`, which `core` lacks.
#[inline]
fn turn_angle(a: f64) -> f64 {
    let r = a % TAU;
    if r < 0.0 {
        r + TAU
    } else {
        r
    }
}

#[inline]
fn check_lengths(lengths: &[f64]) -> Result<(), ArmError> {
    if lengths.iter().all(|l| l.is_finite()) {
        Ok(())
    } else {
        Err(ArmError::NonFinite {
            argument: "lengths",
        })
    }
}

/// `Err(NonFinite { argument })` if `v` holds NaN or an infinity.
#[inline]
pub(crate) fn check_vector<const N: usize>(
    v: &SVector<f64, N>,
    argument: &'static str,
) -> Result<(), ArmError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(ArmError::NonFinite { argument })
    }
}

/// `Ok` when `radius` lies in `inner ..= outer` up to `REACH_TOLERANCE * outer`; the error
/// names `target`, the point the caller asked for, which is the point at `radius` unless the
/// caller replaces it.
#[inline]
fn annulus_check(radius: f64, inner: f64, outer: f64, target: [f64; 2]) -> Result<(), ArmError> {
    annulus_check_with_slack(radius, inner, outer, REACH_TOLERANCE * outer, target, None)
}

#[inline]
fn annulus_check_with_slack(
    radius: f64,
    inner: f64,
    outer: f64,
    slack: f64,
    target: [f64; 2],
    orientation: Option<f64>,
) -> Result<(), ArmError> {
    // How far outside the annulus, beyond the outer circle or inside the hole (at most one
    // of the two is positive).
    let distance = (radius - outer).max(inner - radius);
    if distance > slack {
        return Err(ArmError::Unreachable {
            target,
            orientation,
            radius,
            inner,
            outer,
            distance,
        });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kinematics::test_support::{any_f64, clean, in_range, jacobian, pose_of};
    use nalgebra::{Isometry2, Point2, SMatrix, Vector2, Vector3};
    use proptest::prelude::*;

    // These two hold every file here to the promise of the module docs (NaN and infinities
    // rejected, no panic, no NaN out), so they live with the docs rather than in one file.
    #[test]
    fn non_finite_inputs_are_rejected() {
        let bad = [f64::NAN, f64::INFINITY, f64::NEG_INFINITY];
        for b in bad {
            assert_eq!(ik2(1.0, 0.5, &Point2::new(b, 0.0)), nonfinite("target"));
            assert_eq!(ik2(1.0, 0.5, &Point2::new(0.0, b)), nonfinite("target"));
            assert_eq!(ik2(b, 0.5, &Point2::new(1.0, 0.0)), nonfinite("lengths"));
            assert_eq!(ik2(1.0, b, &Point2::new(1.0, 0.0)), nonfinite("lengths"));
            assert_eq!(ik2_equal(1.0, &Point2::new(b, b)), nonfinite("target"));
            assert_eq!(ik2_equal(b, &Point2::new(1.0, 0.0)), nonfinite("lengths"));
            let pose = Isometry2::new(Vector2::new(1.0, 0.2), 0.1);
            assert_eq!(ik3(1.0, 1.0, b, &pose), nonfinite("lengths"));
            let moved = Isometry2::new(Vector2::new(b, 0.2), 0.1);
            assert_eq!(ik3(1.0, 1.0, 0.2, &moved), nonfinite("target"));
            let turned = Isometry2::new(Vector2::new(1.0, 0.2), b);
            assert_eq!(ik3(1.0, 1.0, 0.2, &turned), nonfinite("target"));

            let q2 = Vector2::new(0.1, 1.0);
            let t2 = Vector2::new(1.0, 2.0);
            assert_eq!(
                tip_force2(1.0, 0.5, &Vector2::new(b, 1.0), &t2),
                nonfinite("q")
            );
            assert_eq!(
                tip_force2(1.0, 0.5, &q2, &Vector2::new(1.0, b)),
                nonfinite("tau")
            );
            assert_eq!(tip_force2(b, 0.5, &q2, &t2), nonfinite("lengths"));
            let q3 = Vector3::new(0.1, 1.0, 0.3);
            let t3 = Vector3::new(1.0, 2.0, 3.0);
            assert_eq!(
                tip_wrench3(1.0, 0.5, 0.2, &Vector3::new(0.0, 1.0, b), &t3),
                nonfinite("q")
            );
            assert_eq!(
                tip_wrench3(1.0, 0.5, 0.2, &q3, &Vector3::new(b, 0.0, 0.0)),
                nonfinite("tau")
            );
            assert_eq!(tip_wrench3(1.0, 0.5, b, &q3, &t3), nonfinite("lengths"));

            let p = Point2::new(b, 0.5);
            assert!(!Workspace::of_lengths(&[1.0, 1.0]).contains(&p));
            assert!(!DexterousWorkspace::of_lengths(1.0, 1.0, 0.5).contains(&p));
            assert!(DexterousWorkspace::of_lengths(1.0, b, 0.5).is_empty());
            assert!(!DexterousWorkspace::of_lengths(1.0, b, 0.5).contains(&Point2::origin()));
            let mut j = jacobian(&[1.0, 1.0, 1.0], &Vector3::new(0.1, 1.0, 0.3));
            j[(1, 2)] = b;
            assert_eq!(manipulability(&j), 0.0);
            assert!(is_singular(&j, 1e-9));

            let l = [1.0, 1.0, 1.0, 1.0];
            let seed = SVector::<f64, 4>::repeat(0.3);
            let solve = |target: IkTarget, seed: &SVector<f64, 4>, options: &DlsOptions<4>| {
                solve_dls(
                    |q| pose_of(&l, q),
                    |q| jacobian(&l, q),
                    &target,
                    seed,
                    options,
                )
            };
            let fine = IkTarget::Position(Point2::new(2.0, 1.0));
            let opts = DlsOptions::default();
            let mut bad_seed = seed;
            bad_seed[2] = b;
            assert_eq!(solve(fine, &bad_seed, &opts), nonfinite("seed"));
            assert_eq!(
                solve(IkTarget::Position(p), &seed, &opts),
                nonfinite("target")
            );
            assert_eq!(
                solve(IkTarget::Pose(turned), &seed, &opts),
                nonfinite("target")
            );
            let bad_opts = DlsOptions { damping: b, ..opts };
            assert_eq!(solve(fine, &seed, &bad_opts), nonfinite("options"));
            let nan_fk = solve_dls(
                |_: &SVector<f64, 4>| Isometry2::new(Vector2::new(b, 0.0), 0.0),
                |q| jacobian(&l, q),
                &fine,
                &seed,
                &opts,
            );
            assert_eq!(nan_fk, nonfinite("fk"));
            let nan_jacobian = solve_dls(
                |q| pose_of(&l, q),
                |_: &SVector<f64, 4>| SMatrix::<f64, 3, 4>::repeat(b),
                &fine,
                &seed,
                &opts,
            );
            assert_eq!(nan_jacobian, nonfinite("jacobian"));
        }
    }

    fn nonfinite<T>(argument: &'static str) -> Result<T, ArmError> {
        Err(ArmError::NonFinite { argument })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(4000))]

        #[test]
        fn no_panic_and_no_nan(
            l in proptest::array::uniform3(any_f64()),
            p in proptest::array::uniform3(any_f64()),
            t in proptest::array::uniform3(any_f64()),
        ) {
            let target = Point2::new(p[0], p[1]);
            for r in [ik2(l[0], l[1], &target), ik2_equal(l[0], &target)] {
                prop_assert!(clean(&r));
                if let Ok(qs) = r {
                    prop_assert!(qs.iter().flatten().all(|a| in_range(*a)));
                }
            }
            let r = ik3(l[0], l[1], l[2], &Isometry2::new(Vector2::new(p[0], p[1]), p[2]));
            prop_assert!(clean(&r));
            if let Ok(qs) = r {
                prop_assert!(qs.iter().flatten().all(|a| in_range(*a)));
            }
            let r = tip_force2(l[0], l[1], &Vector2::new(p[0], p[1]), &Vector2::new(t[0], t[1]));
            prop_assert!(clean(&r));
            if let Ok(f) = r {
                prop_assert!(!f.iter().any(|v| v.is_nan()));
            }
            let r = tip_wrench3(l[0], l[1], l[2], &Vector3::from(p), &Vector3::from(t));
            prop_assert!(clean(&r));
            if let Ok(w) = r {
                prop_assert!(!w.force.iter().any(|v| v.is_nan()) && !w.torque.is_nan());
            }
            for r in [
                inverse_statics(&l, &Vector3::from(p), &Vector3::from(t)).map(|w| (w.force, w.torque, w.residual.amax())),
                inverse_statics(&[l[0], l[1], l[2], p[2]], &SVector::<f64, 4>::new(p[0], p[1], t[0], t[1]), &SVector::<f64, 4>::new(t[2], l[1], p[0], t[0])).map(|w| (w.force, w.torque, w.residual.amax())),
            ] {
                prop_assert!(clean(&r));
                if let Ok((f, torque, residual)) = r {
                    prop_assert!(f.iter().all(|v| v.is_finite()) && torque.is_finite() && residual.is_finite());
                }
            }
            for target in [IkTarget::Position(target), IkTarget::Pose(Isometry2::new(Vector2::new(p[0], p[1]), t[0]))] {
                let r = reachable_target(&l, &target);
                prop_assert!(clean(&r));
            }
            let ranges = [Some((t[0], t[1])), Some((p[2], t[2])), None];
            for r in [
                ik_rp(l[0], l[1], ranges[0], ranges[1], &target),
                ik_pr(l[0], l[1], ranges[1], ranges[0], &target),
                ik2_in_ranges(l[0], l[1], [ranges[0], ranges[1]], &target),
            ] {
                prop_assert!(clean(&r));
                if let Ok(qs) = r {
                    prop_assert!(qs.iter().flatten().all(|a| a.is_finite()));
                }
            }
            let pose = Isometry2::new(Vector2::new(p[0], p[1]), p[2]);
            for r in [ik_prr(l[0], l[1], l[2], ranges, &pose), ik3_in_ranges(l[0], l[1], l[2], ranges, &pose)] {
                prop_assert!(clean(&r));
                if let Ok(qs) = r {
                    prop_assert!(qs.iter().flatten().all(|a| a.is_finite()));
                }
            }
            let kinds = [crate::Joint::Prismatic, crate::Joint::Revolute, crate::Joint::Prismatic];
            let links: [crate::Link; 3] = core::array::from_fn(|i| crate::Link {
                range: ranges[i],
                ..crate::Link::rod(l[i], 1.0).with_joint(kinds[(i + usize::from(t[0] > 0.0)) % 3])
            });
            let w = Workspace::of_links(&links);
            prop_assert!(!w.inner_radius().is_nan() && !w.outer_radius().is_nan() && !w.area().is_nan());
            let _ = w.contains(&target);
            for w in [Workspace::of_links(&links[..2]), Workspace::of_links(&links[1..])] {
                prop_assert!(!w.inner_radius().is_nan() && !w.outer_radius().is_nan() && !w.area().is_nan());
                let _ = w.contains(&target);
            }
            let r = reachable_target_of(&links, &IkTarget::Pose(pose));
            prop_assert!(clean(&r));
            let r = inverse_statics_of(&links, &Vector3::from(p), &Vector3::from(t))
                .map(|w| (w.force, w.torque, w.residual.amax()));
            prop_assert!(clean(&r));
            if let Ok((f, torque, residual)) = r {
                prop_assert!(f.iter().all(|v| v.is_finite()) && torque.is_finite() && residual.is_finite());
            }
            let w = Workspace::of_lengths(&l);
            prop_assert!(!w.inner_radius().is_nan() && !w.outer_radius().is_nan() && !w.area().is_nan());
            let _ = w.contains(&target);
            let d = DexterousWorkspace::of_lengths(l[0], l[1], l[2]);
            prop_assert!(!d.area().is_nan());
            let _ = d.contains(&target);
            let j = SMatrix::<f64, 3, 3>::from_fn(|r, c| [l, p, t][c][r]);
            prop_assert!(!manipulability(&j).is_nan());
            let j2 = SMatrix::<f64, 3, 2>::from_fn(|r, c| [l, p][c][r]);
            prop_assert!(!manipulability(&j2).is_nan());
        }
    }
}
