#[cfg(not(feature = "std"))]
use num_traits::Float as _;

use nalgebra::{SVector, Vector2};

use crate::{ArmError, Joint, Link};

/// A rigid body held at the tip of the last link: a tool, a gripper and what it carries.
///
/// It turns with the last link. Its centre of mass is at `tip + com.x u + com.y perp(u)`, with
/// `u` the direction of the last link (the same frame as [`Link::com`], moved to the tip).
///
/// # Example
///
/// ```
/// use planar_arm::Payload;
///
/// // 0.5 kg held 10 cm beyond the tip, a disc of radius 4 cm.
/// let load = Payload::point(0.5).with_com(0.1, 0.0).with_inertia(0.5 * 0.5 * 0.04 * 0.04);
/// assert_eq!(load.com.x, 0.1);
/// assert_eq!(Payload::NONE.mass, 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Payload {
    /// Mass, kilograms.
    pub mass: f64,
    /// Moment of inertia about the payload's own centre of mass, kg m^2.
    pub inertia: f64,
    /// The payload's centre of mass relative to the tip, in the last link's frame (`x` along
    /// the last link, `y` perpendicular, counter-clockwise), metres.
    pub com: Vector2<f64>,
}

impl Payload {
    /// No payload: zero mass and inertia.
    pub const NONE: Payload = Payload {
        mass: 0.0,
        inertia: 0.0,
        com: Vector2::new(0.0, 0.0),
    };

    /// A point mass (kg) exactly at the tip.
    #[must_use]
    pub const fn point(mass: f64) -> Self {
        Self { mass, ..Self::NONE }
    }

    /// The same payload with its centre of mass at `(x, y)` from the tip in the last link's
    /// frame, metres.
    #[must_use]
    pub const fn with_com(self, x: f64, y: f64) -> Self {
        Self {
            com: Vector2::new(x, y),
            ..self
        }
    }

    /// The same payload with the given moment of inertia about its centre of mass, kg m^2.
    #[must_use]
    pub const fn with_inertia(self, inertia: f64) -> Self {
        Self { inertia, ..self }
    }
}

/// Everything the dynamics of a planar arm depend on: its links base first, gravity and a
/// payload at the tip.
///
/// Gravity is an acceleration in the base frame: [`Model::new`] takes a magnitude along -y,
/// [`Model::with_gravity`] any direction (a model file's arm whose links point up at
/// `q = 0` has its gravity along -x, say).
///
/// The functions of [`reference`](crate::reference) take a model. A derived arm's model, with
/// its run-time parameters' current values, is [`PlanarArm::model`](crate::PlanarArm::model).
///
/// # Example
///
/// ```
/// use planar_arm::{reference, Link, Model, Payload};
/// use planar_arm::nalgebra::Vector2;
///
/// let arm = Model::new([Link::rod(1.0, 1.0), Link::rod(1.0, 1.0)], 9.81)
///     .with_payload(Payload::point(0.5));
/// let q = Vector2::new(0.3, 1.2);
/// let m = reference::mass_matrix(&arm, &q);
/// // The payload adds 0.5 |tip - joint 2|^2 = 0.5 kg m^2 to M22.
/// assert!((m[(1, 1)] - (1.0 / 3.0 + 0.5)).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Model<const N: usize> {
    /// The links, base first.
    pub links: [Link; N],
    /// Gravity's acceleration in the base frame, m/s^2: `(0, -9.81)` for gravity along -y.
    pub gravity: Vector2<f64>,
    /// The body held at the tip ([`Payload::NONE`] for none).
    pub payload: Payload,
}

impl<const N: usize> Model<N> {
    /// An arm of these links under gravity of magnitude `gravity` (m/s^2) along -y, with no
    /// payload.
    #[must_use]
    pub const fn new(links: [Link; N], gravity: f64) -> Self {
        Self {
            links,
            gravity: Vector2::new(0.0, -gravity),
            payload: Payload::NONE,
        }
    }

    /// The same arm under gravity of acceleration `gravity` (m/s^2, in the base frame).
    ///
    /// ```
    /// use planar_arm::{reference, Link, Model};
    /// use planar_arm::nalgebra::{Vector1, Vector2};
    ///
    /// // A pendulum that hangs along -x at q = 0 under gravity along -x: no torque holds it.
    /// let arm = Model::new([Link::rod(1.0, 1.0)], 0.0).with_gravity(Vector2::new(-9.81, 0.0));
    /// let g = reference::gravity_torques(&arm, &Vector1::new(core::f64::consts::PI));
    /// assert!(g[0].abs() < 1e-14);
    /// ```
    #[must_use]
    pub const fn with_gravity(self, gravity: Vector2<f64>) -> Self {
        Self { gravity, ..self }
    }

    /// The same arm as a spatial arm in MuJoCo's x-y plane: each joint a URDF-style joint at the
    /// previous link's end (the base origin for the first), turned about `z` by its offset, a
    /// hinge about `+z` or a slide along its `x` (`-z`, `-x` reversed); each link's centre of mass at `(x, y, 0)`; the tool at the last link's end; the payload as the tool's. A planar body
    /// has one moment of inertia, about `z`: the tensor's out-of-plane moments, which a planar
    /// motion never feels, are set equal to it, so that the tensor meets the triangle
    /// inequality MuJoCo requires. Gravity is `(gx, gy, 0)`. Its dynamics are this arm's (`tests/models.rs` checks the
    /// spatial reference against the planar arms).
    #[must_use]
    pub fn to_spatial(&self) -> crate::spatial::SpatialModel<N> {
        use crate::spatial::{JointGeometry, SpatialJoint, SpatialLink, SpatialModel};
        use nalgebra::{Isometry3, Matrix3, Vector3};
        let body = |mass: f64, inertia: f64, com: Vector2<f64>| SpatialLink {
            mass,
            com: Vector3::new(com.x, com.y, 0.0),
            inertia: Matrix3::from_diagonal_element(inertia),
        };
        let mut before = 0.0;
        let joints = self.links.map(|l| {
            let axis = match l.joint {
                crate::Joint::Revolute => Vector3::z(),
                crate::Joint::Prismatic => Vector3::x(),
            };
            let geometry = JointGeometry::Urdf {
                xyz: Vector3::new(before, 0.0, 0.0),
                rpy: Vector3::new(0.0, 0.0, l.offset),
                axis: if l.reversed { -axis } else { axis },
            };
            before = l.length;
            SpatialJoint {
                geometry,
                kind: l.joint,
                range: l.range,
                armature: l.armature,
                damping: l.damping,
                frictionloss: l.frictionloss,
                stiffness: l.stiffness,
                springref: l.springref,
            }
        });
        let p = &self.payload;
        SpatialModel {
            joints,
            links: self.links.map(|l| body(l.mass, l.inertia, l.com)),
            gravity: Vector3::new(self.gravity.x, self.gravity.y, 0.0),
            tool: Isometry3::translation(before, 0.0, 0.0),
            payload: (p.mass != 0.0 || p.inertia != 0.0).then(|| body(p.mass, p.inertia, p.com)),
        }
    }

    /// The same arm holding `payload` at its tip (in place of any payload it held).
    #[must_use]
    pub const fn with_payload(self, payload: Payload) -> Self {
        Self { payload, ..self }
    }

    /// The links with the payload merged into the last one: what a rigid-body solver sees.
    ///
    /// The last link's mass becomes the sum of the two masses, its centre of mass their
    /// mass-weighted mean in the link's frame (the payload's centre is at
    /// `(length + com.x, com.y)` there), and its inertia about the new centre the sum of both
    /// inertias moved there by the parallel-axis theorem. Joint parameters are unchanged. If
    /// both masses are zero the centre of mass stays the link's and the inertias add. With no
    /// links there is nothing to merge into and the payload is dropped.
    #[must_use]
    pub fn rigid_links(&self) -> [Link; N] {
        let mut links = self.links;
        if let Some(last) = links.last_mut() {
            let p = &self.payload;
            let p_com = Vector2::new(last.length + p.com.x, p.com.y);
            let mass = last.mass + p.mass;
            let com = if mass == 0.0 {
                last.com
            } else {
                (last.com * last.mass + p_com * p.mass) / mass
            };
            last.inertia += p.inertia
                + last.mass * (last.com - com).norm_squared()
                + p.mass * (p_com - com).norm_squared();
            last.mass = mass;
            last.com = com;
        }
        links
    }

    /// Checks that the model is physical and its dynamics defined: every value finite, masses,
    /// lengths, inertias, armatures, damping, frictionloss, stiffness, the payload's mass and inertia not
    /// negative (a massless link is fine where later links carry its joint's load), a joint range finite with `lower < upper`, and the mass
    /// matrix positive definite (at a generic configuration its `L D L^T` pivots exceed
    /// [`RELATIVE_PIVOT`] times their diagonal entries, which are normal `f64`s: no joint that
    /// moves no mass and turns no inertia). What the derive checks at compile time for literal
    /// values, by the same test, for values that are read at run time (identified, loaded from
    /// a file). With `Ok`, forward dynamics is finite wherever `M` is definite, which for
    /// ordinary arms is everywhere.
    ///
    /// # Errors
    /// [`ArmError::OutOfRange`] naming the first value that is not; for the mass matrix,
    /// `what = "mass matrix"`, the joint whose pivot failed and the pivot relative to its
    /// diagonal entry.
    ///
    /// # Example
    ///
    /// ```
    /// use planar_arm::{ArmError, Link, Model};
    ///
    /// let ok = Model::new([Link::rod(0.5, 2.0)], 9.81);
    /// assert!(ok.check().is_ok());
    /// let bad = Model::new([Link::rod(0.5, -2.0)], 9.81);
    /// assert!(matches!(bad.check(), Err(ArmError::OutOfRange { what: "mass", link: Some(0), .. })));
    /// ```
    pub fn check(&self) -> Result<(), ArmError> {
        let fail = |what, link, value| Err(ArmError::OutOfRange { what, link, value });
        for (i, l) in self.links.iter().enumerate() {
            let values = [
                ("length", l.length, false),
                ("mass", l.mass, false),
                ("inertia", l.inertia, false),
                ("com.x", l.com.x, false),
                ("com.y", l.com.y, false),
                ("armature", l.armature, false),
                ("damping", l.damping, false),
                ("frictionloss", l.frictionloss, false),
                ("offset", l.offset, false),
                ("stiffness", l.stiffness, false),
                ("springref", l.springref, false),
            ];
            for (what, value, positive) in values {
                let signed = matches!(what, "com.x" | "com.y" | "offset" | "springref");
                if !value.is_finite()
                    || (positive && value <= 0.0)
                    || (!signed && !positive && value < 0.0)
                {
                    return fail(what, Some(i), value);
                }
            }
            if let Some((lower, upper)) = l.range {
                if !lower.is_finite() || !upper.is_finite() {
                    return fail(
                        "range",
                        Some(i),
                        if lower.is_finite() { upper } else { lower },
                    );
                }
                if lower >= upper {
                    return fail("range", Some(i), lower);
                }
            }
        }
        let p = &self.payload;
        for (what, value, signed) in [
            ("payload mass", p.mass, false),
            ("payload inertia", p.inertia, false),
            ("payload com.x", p.com.x, true),
            ("payload com.y", p.com.y, true),
            ("gravity.x", self.gravity.x, true),
            ("gravity.y", self.gravity.y, true),
        ] {
            if !value.is_finite() || (!signed && value < 0.0) {
                return fail(what, None, value);
            }
        }
        self.check_definite()
    }

    /// `Err` when the mass matrix is singular at a generic configuration (the same test and the
    /// same configuration as the derive's for literal values): its `L D L^T` pivot at some
    /// joint is at most [`RELATIVE_PIVOT`] of its diagonal entry, or that entry is not a normal
    /// `f64`.
    fn check_definite(&self) -> Result<(), ArmError> {
        let q = SVector::<f64, N>::from_fn(|k, _| generic_joint_value(self.links[k].joint, k));
        let m = crate::reference::mass_matrix(self, &q);
        let mut d = [0.0_f64; N];
        let mut l = [[0.0_f64; N]; N];
        for j in 0..N {
            let diagonal = m[(j, j)];
            let pivot = diagonal - (0..j).map(|k| l[j][k] * l[j][k] * d[k]).sum::<f64>();
            let normal = diagonal.is_finite() && diagonal >= f64::MIN_POSITIVE;
            if !normal || pivot.is_nan() || pivot <= RELATIVE_PIVOT * diagonal {
                let relative = if normal {
                    (pivot / diagonal).max(0.0)
                } else {
                    0.0
                };
                return Err(ArmError::OutOfRange {
                    what: "mass matrix",
                    link: Some(j),
                    value: relative,
                });
            }
            for i in j + 1..N {
                l[i][j] =
                    (m[(i, j)] - (0..j).map(|k| l[i][k] * l[j][k] * d[k]).sum::<f64>()) / pivot;
            }
            d[j] = pivot;
        }
        Ok(())
    }
}

/// Pivots of the mass matrix at or below this fraction of their diagonal entry make
/// [`Model::check`] refuse the arm (as the derive refuses literal values): four rounding errors
/// of that entry, below which an `f64` evaluation of the pivot cannot tell it from zero.
/// Ill-conditioned but regular arms (relative pivots of 1e-14) pass.
pub const RELATIVE_PIVOT: f64 = 4.0 * f64::EPSILON;

/// Joint `k`'s value at the configuration [`Model::check`] tests the mass matrix at: a hinge's
/// angle has the Pythagorean cosine and sine of the derive's own test (3/5 and 4/5, 5/13 and
/// -12/13, ...), a slide's displacement is `(1 + k mod 5) / 7` m.
#[must_use]
pub(crate) fn generic_joint_value(joint: Joint, k: usize) -> f64 {
    const TRIPLES: [(f64, f64); 8] = [
        (3.0, 4.0),
        (5.0, 12.0),
        (8.0, 15.0),
        (7.0, 24.0),
        (20.0, 21.0),
        (12.0, 35.0),
        (9.0, 40.0),
        (28.0, 45.0),
    ];
    match joint {
        Joint::Revolute => {
            let (a, b) = TRIPLES[k % TRIPLES.len()];
            let sign = if k.is_multiple_of(2) { 1.0 } else { -1.0 };
            (sign * b).atan2(a)
        }
        Joint::Prismatic => (1.0 + (k % 5) as f64) / 7.0,
    }
}
