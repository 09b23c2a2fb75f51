use nalgebra::Vector2;

/// The zero-sized marker type of a revolute link field in a `#[derive(PlanarArm)]` struct.
///
/// It carries no data: the link's parameters live in its `#[arm(...)]` attribute and are baked
/// into the generated code at compile time.
#[derive(Default, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Revolute;

/// The zero-sized marker type of a prismatic (sliding) link field in a `#[derive(PlanarArm)]`
/// struct.
///
/// Its joint slides the link along the previous link's direction (for the first link, +x of
/// the base) by `q_i` metres without turning it: the link's frame origin is at the previous
/// link's end plus `q_i` along that direction. The joint's generalised force is a force
/// (newtons), its armature a reflected mass (kg), its damping N s/m and its frictionloss N.
#[derive(Default, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Prismatic;

/// The kind of a link's joint.
#[derive(Default, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Joint {
    /// A hinge: `q_i` is the link's angle relative to the previous link, radians; its
    /// generalised force is a torque.
    #[default]
    Revolute,
    /// A slider along the previous link's direction: `q_i` is the displacement, metres; its
    /// generalised force is a force (see [`Prismatic`]).
    Prismatic,
}

/// The numeric parameters of one link and of the joint that drives it, in SI units, as `f64`.
///
/// A derived arm exposes them as [`PlanarArm::links`](crate::PlanarArm::links) so that numeric
/// code (the [`reference`](crate::reference) implementations, a simulator) can model the same
/// arm; a [`Model`](crate::Model) gathers them with gravity and a payload.
///
/// The joint parameters are named as in MuJoCo's MJCF (`armature`, `damping`, `frictionloss`)
/// and mean the same: with them the equations of motion are
/// `tau = M(q) qdd + c(q, qd) + g(q) + f(qd)`, the armature inside `M`, the friction in `f`.
///
/// # Example
///
/// ```
/// use planar_arm::Link;
///
/// // A 0.4 m rod of 2 kg whose centre of mass sits 3 cm to the left of its axis, driven
/// // through a gearbox that reflects 0.01 kg m^2 of rotor inertia.
/// let link = Link::rod(0.4, 2.0).with_com(0.2, 0.03).with_armature(0.01).with_damping(0.1);
/// assert_eq!(link.inertia, 2.0 * 0.4 * 0.4 / 12.0);
/// assert!((link.inertia_about_joint() - (link.inertia + 2.0 * (0.04 + 0.0009))).abs() < 1e-15);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Link {
    /// Distance from this link's joint to the next joint (or to the tip), metres.
    pub length: f64,
    /// Mass, kilograms.
    pub mass: f64,
    /// Moment of inertia about the link's centre of mass, kg m^2.
    pub inertia: f64,
    /// The centre of mass in the link's own frame, metres: `x` along the link from its joint
    /// toward the next joint, `y` perpendicular to it, counter-clockwise (to the left looking
    /// from the joint along the link).
    ///
    /// In the world it sits at `joint + x u + y perp(u)`, where `u = (cos phi, sin phi)` is the
    /// direction of the link at its absolute angle `phi` and `perp(u) = (-sin phi, cos phi)`.
    pub com: Vector2<f64>,
    /// MuJoCo's `armature`: the reflected inertia of the joint's rotor, its own inertia times
    /// the square of the gear ratio, kg m^2.
    ///
    /// It is added to the mass matrix's diagonal entry of this joint, and the kinetic energy
    /// gains `armature * qd_i^2 / 2` with `qd_i` the joint's own (relative) rate. For a
    /// [`Joint::Prismatic`] joint it is a reflected mass, kg.
    pub armature: f64,
    /// MuJoCo's `damping`: viscous friction, a torque `damping * qd_i` opposing the joint's
    /// rate, N m s/rad (for a prismatic joint a force, N s/m).
    pub damping: f64,
    /// MuJoCo's `frictionloss`: Coulomb (dry) friction, a torque
    /// `frictionloss * sign(qd_i)` with `sign(0) = 0`, N m (for a prismatic joint a force, N).
    pub frictionloss: f64,
    /// The kind of the joint that drives the link. For a [`Joint::Prismatic`] joint the
    /// armature is a reflected mass (kg), the damping N s/m and the frictionloss N.
    pub joint: Joint,
    /// The joint's range `(lower, upper)`, radians or metres, if it has one: used by the
    /// work-spaces, inverse kinematics and documentation, never to clamp the dynamics.
    pub range: Option<(f64, f64)>,
    /// The joint's offset, radians: a hinge's link angle at `q_i = 0` relative to the
    /// previous link, or the direction a slide moves in relative to the previous link (the
    /// slide's frame turns with it, so the next link's angle is measured from it). Zero for
    /// the paper's arms, whose links all lie along +x at `q = 0`.
    pub offset: f64,
    /// Whether the joint turns (slides) the other way: the link's angle relative to the
    /// previous one is `offset - q_i` (the slide's displacement `-q_i`), and the joint's
    /// generalised force is the torque (force) in that sense: a hinge about `-z` among `+z`
    /// ones, as model files have them.
    pub reversed: bool,
    /// MuJoCo's `stiffness`: a joint spring pulling toward [`springref`](Self::springref)
    /// with the torque `stiffness (q_i - springref)`, N m/rad (N/m for a slide). Its energy
    /// `stiffness (q_i - springref)^2 / 2` is part of the potential energy, so the torque is
    /// part of `gravity` (`g = dV/dq`), `bias` and the equations of motion.
    pub stiffness: f64,
    /// MuJoCo's `springref`: the joint value at which the spring is slack, rad or m.
    pub springref: f64,
}

impl Link {
    /// A uniform rod of the given length (m) and mass (kg): inertia `m l^2 / 12`, centre of
    /// mass on the link at `l / 2`, no armature and no friction.
    #[must_use]
    pub const fn rod(length: f64, mass: f64) -> Self {
        Self {
            length,
            mass,
            inertia: mass * length * length / 12.0,
            com: Vector2::new(length / 2.0, 0.0),
            armature: 0.0,
            damping: 0.0,
            frictionloss: 0.0,
            joint: Joint::Revolute,
            range: None,
            offset: 0.0,
            reversed: false,
            stiffness: 0.0,
            springref: 0.0,
        }
    }

    /// The same link with a joint spring of this stiffness, slack at `springref`.
    #[must_use]
    pub const fn with_spring(self, stiffness: f64, springref: f64) -> Self {
        Self {
            stiffness,
            springref,
            ..self
        }
    }

    /// The same link with its joint's [`offset`](Self::offset), radians.
    #[must_use]
    pub const fn with_offset(self, offset: f64) -> Self {
        Self { offset, ..self }
    }

    /// The same link with its joint [`reversed`](Self::reversed).
    #[must_use]
    pub const fn reversed(self) -> Self {
        Self {
            reversed: true,
            ..self
        }
    }

    /// The same link driven by a joint of the given kind.
    #[must_use]
    pub const fn with_joint(self, joint: Joint) -> Self {
        Self { joint, ..self }
    }

    /// The same link with the joint range `lower..=upper` (radians or metres).
    #[must_use]
    pub const fn with_range(self, lower: f64, upper: f64) -> Self {
        Self {
            range: Some((lower, upper)),
            ..self
        }
    }

    /// The same link with its centre of mass at `(x, y)` in its own frame, metres (see
    /// [`com`](Self::com)); the inertia about the centre of mass is unchanged.
    #[must_use]
    pub const fn with_com(self, x: f64, y: f64) -> Self {
        Self {
            com: Vector2::new(x, y),
            ..self
        }
    }

    /// The same link with the given moment of inertia about its centre of mass, kg m^2.
    #[must_use]
    pub const fn with_inertia(self, inertia: f64) -> Self {
        Self { inertia, ..self }
    }

    /// The same link with the given [`armature`](Self::armature), kg m^2.
    #[must_use]
    pub const fn with_armature(self, armature: f64) -> Self {
        Self { armature, ..self }
    }

    /// The same link with the given viscous [`damping`](Self::damping), N m s/rad.
    #[must_use]
    pub const fn with_damping(self, damping: f64) -> Self {
        Self { damping, ..self }
    }

    /// The same link with the given Coulomb [`frictionloss`](Self::frictionloss), N m.
    #[must_use]
    pub const fn with_frictionloss(self, frictionloss: f64) -> Self {
        Self {
            frictionloss,
            ..self
        }
    }

    /// The link's moment of inertia about its own joint, `inertia + mass |com|^2` (parallel
    /// axis theorem), kg m^2; the armature is not included.
    #[must_use]
    pub fn inertia_about_joint(&self) -> f64 {
        self.inertia + self.mass * self.com.norm_squared()
    }
}
