//! The numeric description of a spatial arm: joints, links' mass properties, gravity, tool.

use nalgebra::{Isometry3, Matrix3, Vector3};

use super::JointGeometry;
use crate::{ArmError, Joint};

/// One joint of a spatial arm and the link it moves: geometry, kind, range and the joint's
/// MuJoCo parameters.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialJoint {
    /// Where the joint sits and how it moves.
    pub geometry: JointGeometry,
    /// Hinge or slide.
    pub kind: Joint,
    /// The joint's travel `(lower, upper)` (radians or metres), if limited.
    pub range: Option<(f64, f64)>,
    /// Reflected rotor inertia (kg m², or kg for a slide).
    pub armature: f64,
    /// Viscous friction (N m s/rad, or N s/m).
    pub damping: f64,
    /// Coulomb friction (N m, or N).
    pub frictionloss: f64,
    /// The joint spring's stiffness (N m/rad, or N/m), MuJoCo's: a torque
    /// `stiffness (q - springref)` pulling the joint toward `springref`, whose energy
    /// `stiffness (q - springref)^2 / 2` is part of the potential energy, so that the static
    /// torques `gravity(q) = dV/dq` hold it.
    pub stiffness: f64,
    /// Where the spring is relaxed (radians, or metres).
    pub springref: f64,
}

impl SpatialJoint {
    /// A joint of this geometry and kind, unlimited, without armature or friction.
    #[must_use]
    pub const fn new(geometry: JointGeometry, kind: Joint) -> Self {
        Self {
            geometry,
            kind,
            range: None,
            armature: 0.0,
            damping: 0.0,
            frictionloss: 0.0,
            stiffness: 0.0,
            springref: 0.0,
        }
    }

    /// The same joint limited to `lower ..= upper`.
    #[must_use]
    pub const fn with_range(self, lower: f64, upper: f64) -> Self {
        Self {
            range: Some((lower, upper)),
            ..self
        }
    }
}

/// A link's mass properties in its own frame (the frame its joint's convention defines).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialLink {
    /// Mass, kg.
    pub mass: f64,
    /// Centre of mass, m, in the link's frame.
    pub com: Vector3<f64>,
    /// Inertia tensor about the centre of mass in the link's axes, kg m² (URDF's
    /// `<inertia ixx ixy ixz iyy iyz izz>`).
    pub inertia: Matrix3<f64>,
}

impl SpatialLink {
    /// Mass not negative, every value finite, the tensor symmetric with no negative moment on
    /// the diagonal; `what` names the mass, the values, the symmetry and the moments in errors.
    fn check(&self, link: Option<usize>, what: [&'static str; 4]) -> Result<(), ArmError> {
        let fail = |what, value| Err(ArmError::OutOfRange { what, link, value });
        if !self.mass.is_finite() || self.mass < 0.0 {
            return fail(what[0], self.mass);
        }
        if let Some(bad) = self
            .com
            .iter()
            .chain(self.inertia.iter())
            .find(|v| !v.is_finite())
        {
            return fail(what[1], *bad);
        }
        let t = &self.inertia;
        let asymmetry = (t - t.transpose()).amax();
        if asymmetry > 1e-12 * t.amax() {
            return fail(what[2], asymmetry);
        }
        if let Some(bad) = (0..3).map(|k| t[(k, k)]).find(|d| *d < 0.0) {
            return fail(what[3], bad);
        }
        Ok(())
    }

    /// No mass.
    pub const MASSLESS: Self = Self {
        mass: 0.0,
        com: Vector3::new(0.0, 0.0, 0.0),
        inertia: Matrix3::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    };
}

/// Everything the kinematics and gravity of a spatial arm depend on: joints and links base
/// first, gravity, and the tool frame in the last link's frame.
///
/// The functions of [`reference::spatial`](crate::reference::spatial) take it; a derived arm's
/// is [`SpatialArm::model`](crate::spatial::SpatialArm::model).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpatialModel<const N: usize> {
    /// The joints, base first.
    pub joints: [SpatialJoint; N],
    /// Each joint's link.
    pub links: [SpatialLink; N],
    /// Gravity, m/s², in the base frame.
    pub gravity: Vector3<f64>,
    /// The tool frame in the last link's frame.
    pub tool: Isometry3<f64>,
    /// A payload held rigidly at the tool: its mass, its centre of mass in the tool frame and
    /// its inertia about that centre in the tool's axes.
    pub payload: Option<SpatialLink>,
}

impl<const N: usize> SpatialModel<N> {
    /// Checks that the model is usable: every value finite, masses, armature, friction and
    /// spring stiffness not negative, inertia tensors symmetric with no negative moment on the diagonal, ranges with
    /// `lower < upper`, and URDF axes not zero. The triangle inequality of the moments is not
    /// required: published models break it (Corke's PUMA 560), as the derive allows.
    ///
    /// # Errors
    /// [`ArmError::OutOfRange`] naming the first value that is not.
    pub fn check(&self) -> Result<(), ArmError> {
        let fail = |what, link, value| Err(ArmError::OutOfRange { what, link, value });
        for (i, (j, l)) in self.joints.iter().zip(&self.links).enumerate() {
            let lengths: [f64; 4] = match j.geometry {
                JointGeometry::Dh { a, alpha, d, theta }
                | JointGeometry::Mdh { a, alpha, d, theta } => [a, alpha, d, theta],
                JointGeometry::Urdf { xyz, rpy, axis } => {
                    if axis.norm().is_nan() || axis.norm() <= 0.0 {
                        return fail("axis", Some(i), axis.norm());
                    }
                    if let Some(bad) = xyz.iter().chain(rpy.iter()).find(|v| !v.is_finite()) {
                        return fail("origin", Some(i), *bad);
                    }
                    [0.0; 4]
                }
            };
            if let Some(bad) = lengths.iter().find(|v| !v.is_finite()) {
                return fail("geometry", Some(i), *bad);
            }
            for (what, value) in [
                ("armature", j.armature),
                ("damping", j.damping),
                ("frictionloss", j.frictionloss),
                ("stiffness", j.stiffness),
            ] {
                if !value.is_finite() || value < 0.0 {
                    return fail(what, Some(i), value);
                }
            }
            if !j.springref.is_finite() {
                return fail("springref", Some(i), j.springref);
            }
            l.check(
                Some(i),
                ["mass", "com or inertia", "inertia symmetry", "inertia"],
            )?;
            if let Some((lower, upper)) = j.range {
                if !lower.is_finite() || !upper.is_finite() || lower >= upper {
                    return fail("range", Some(i), lower);
                }
            }
        }
        if let Some(payload) = &self.payload {
            payload.check(
                None,
                [
                    "payload mass",
                    "payload com or inertia",
                    "payload inertia symmetry",
                    "payload inertia",
                ],
            )?;
        }
        if let Some(bad) = self.gravity.iter().find(|v| !v.is_finite()) {
            return fail("gravity", None, *bad);
        }
        Ok(())
    }
}
