//! The planar arm as the derive reads it: links and their joints, gravity, a payload, with
//! exact values or polynomials in run-time parameters.

use crate::mechanics::spatial::FixedAngle;
use crate::poly::{Param, Poly};
use crate::ring::{int, ratio, Coefficient, Rational};

/// The kind of a link's joint.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum JointKind {
    /// A hinge: `q_i` is the link's angle relative to the previous link.
    #[default]
    Revolute,
    /// A slider along the previous link's direction (for the first link, +x of the base),
    /// turned by the joint's offset: `q_i` is the displacement; the link does not turn with
    /// `q_i`.
    Prismatic,
}

/// A joint's constant turn: a hinge's link angle at `q_i = 0` relative to the previous link,
/// or the direction a slide moves in relative to the previous link (its frame turns with it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Offset<C = Rational> {
    /// The angle.
    pub angle: FixedAngle,
    /// Its cosine: exact at the quarter turns (and the rational values of `pi/3`, `pi/6`),
    /// a named constant otherwise.
    pub cos: C,
    /// Its sine, likewise.
    pub sin: C,
}

/// One link and its joint: exact parameters (or polynomials in run-time parameters).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LinkSpec<C = Rational> {
    /// Joint-to-joint length.
    pub length: C,
    /// Mass.
    pub mass: C,
    /// Moment of inertia about the centre of mass.
    pub inertia: C,
    /// The centre of mass in the link's frame: `.0` along the link from its own joint toward
    /// the next, `.1` perpendicular to it, counter-clockwise.
    pub com: (C, C),
    /// Reflected rotor inertia at this link's joint (MuJoCo's `armature`): kinetic energy
    /// `armature qd_i^2 / 2`, so it adds to `M_ii`.
    pub armature: C,
    /// Viscous friction at this link's joint: torque `damping qd_i`.
    pub damping: C,
    /// Coulomb friction at this link's joint: torque `frictionloss sign(qd_i)`.
    pub frictionloss: C,
    /// The joint spring's stiffness (MuJoCo's `stiffness`): energy
    /// `stiffness (q_i - springref)^2 / 2`, part of the potential, so a torque
    /// `stiffness (q_i - springref)` in `g`.
    pub stiffness: C,
    /// The joint's angle (or displacement) at which its spring is slack (MuJoCo's
    /// `springref`).
    pub springref: C,
    /// The joint's kind.
    pub joint: JointKind,
    /// The joint's range `(lower, upper)`, if given: kinematics only, never the dynamics.
    pub range: Option<(Rational, Rational)>,
    /// The joint's offset (`None`: zero), see [`Offset`].
    pub offset: Option<Offset<C>>,
    /// Whether the joint turns (slides) the other way: the link's angle (the slide's
    /// displacement) is `-q_i`, and its generalised force is the torque (force) along `-z`
    /// (`-x` of its frame).
    pub reversed: bool,
}

impl<C: Coefficient> LinkSpec<C> {
    /// A uniform rod: inertia `m l^2 / 12`, centre of mass at `(l / 2, 0)`, no armature, no
    /// friction.
    #[must_use]
    pub fn rod(length: C, mass: C) -> Self {
        let zero = C::from_rational(int(0));
        Self {
            inertia: (mass.clone() * length.clone() * length.clone()).scale(&ratio(1, 12)),
            com: (length.scale(&ratio(1, 2)), zero.clone()),
            length,
            mass,
            armature: zero.clone(),
            damping: zero.clone(),
            frictionloss: zero.clone(),
            stiffness: zero.clone(),
            springref: zero,
            joint: JointKind::Revolute,
            range: None,
            offset: None,
            reversed: false,
        }
    }
}

/// Gravity of magnitude `g` along -y, as an acceleration `(0, -g)`.
#[must_use]
pub fn down<C: Coefficient>(g: C) -> (C, C) {
    (C::from_rational(int(0)), -g)
}

/// A body rigidly held at the tip of the last link: a payload, a tool, a gripper.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PayloadSpec<C = Rational> {
    /// Mass.
    pub mass: C,
    /// Moment of inertia about its own centre of mass.
    pub inertia: C,
    /// Its centre of mass relative to the tip, in the last link's frame.
    pub com: (C, C),
}

/// A planar serial arm, base first, under gravity `gravity` and perhaps with a payload at the
/// tip.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ArmSpec<C = Rational> {
    /// The links, base first.
    pub links: Vec<LinkSpec<C>>,
    /// Gravity's acceleration `(gx, gy)` in the base frame: `(0, -g)` for gravity of
    /// magnitude `g` along -y ([`down`]), the paper's and most arms'.
    pub gravity: (C, C),
    /// The body held at the tip, if any.
    pub payload: Option<PayloadSpec<C>>,
}

impl ArmSpec<Rational> {
    /// `n` equal uniform rods of unit length and mass, no gravity: the paper's equal links.
    #[must_use]
    pub fn paper(n: usize) -> Self {
        Self {
            links: vec![LinkSpec::rod(int(1), int(1)); n],
            gravity: down(int(0)),
            payload: None,
        }
    }
}

impl<C: Coefficient> ArmSpec<C> {
    /// `1` or `-1`: the sense joint `i` turns (slides) in.
    #[must_use]
    pub fn sense(&self, i: usize) -> i32 {
        if self.links[i].reversed {
            -1
        } else {
            1
        }
    }

    /// `(cos, sin)` of the offsets of joints `0..=i` together: link `i`'s frame turned from
    /// the angle its joints' `q` give it.
    #[must_use]
    pub fn turn(&self, i: usize) -> (C, C) {
        let mut t = (C::from_rational(int(1)), C::from_rational(int(0)));
        for o in self.links[..=i].iter().filter_map(|l| l.offset.as_ref()) {
            t = (
                t.0.clone() * o.cos.clone() - t.1.clone() * o.sin.clone(),
                t.1 * o.cos.clone() + t.0 * o.sin.clone(),
            );
        }
        t
    }

    /// `v`, given in link `i`'s frame, in the frame whose angle is the one link `i`'s joints'
    /// `q` give (`R(turn) v`).
    #[must_use]
    pub fn turned(&self, i: usize, v: &(C, C)) -> (C, C) {
        if self.links[..=i].iter().all(|l| l.offset.is_none()) {
            return v.clone();
        }
        let (c, s) = self.turn(i);
        (
            c.clone() * v.0.clone() - s.clone() * v.1.clone(),
            s * v.0.clone() + c * v.1.clone(),
        )
    }
}

impl ArmSpec<Poly> {
    /// The arm over the rationals, if no value names a run-time parameter (or a named
    /// constant): what the literal arms' exact paths take.
    #[must_use]
    pub fn as_rational(&self) -> Option<ArmSpec<Rational>> {
        let mut numbers = true;
        let spec = self.map(|c| {
            let r = c.as_rational();
            numbers &= r.is_some();
            r.unwrap_or_default()
        });
        numbers.then_some(spec)
    }
}

impl ArmSpec<Rational> {
    /// The same arm with every value a run-time parameter, named `v0, v1, ...` in the order
    /// link by link (length, mass, inertia, com x, com y, armature, damping, frictionloss),
    /// then gravity (x, y), then the payload's; and each parameter's value. The derivation over it,
    /// evaluated at those values, must give the literal arm's numbers: a check of the
    /// polynomial path against the rational one.
    #[must_use]
    pub fn parameterised(&self) -> (ArmSpec<Poly>, Vec<(Param, Rational)>) {
        let mut values = Vec::new();
        let param = |r: &Rational| {
            let p = Param::new(&format!("v{}", values.len()));
            values.push((p.clone(), r.clone()));
            Poly::param(p)
        };
        (self.map(param), values)
    }
}

impl<C> ArmSpec<C> {
    /// The same arm with every value mapped by `f`, in the order link by link (length, mass,
    /// inertia, com x, com y, armature, damping, frictionloss), then gravity (x, y), then the
    /// payload's (mass, inertia, com x, com y).
    #[must_use]
    pub fn map<D>(&self, mut f: impl FnMut(&C) -> D) -> ArmSpec<D> {
        let links = self
            .links
            .iter()
            .map(|l| LinkSpec {
                length: f(&l.length),
                mass: f(&l.mass),
                inertia: f(&l.inertia),
                com: (f(&l.com.0), f(&l.com.1)),
                armature: f(&l.armature),
                damping: f(&l.damping),
                frictionloss: f(&l.frictionloss),
                stiffness: f(&l.stiffness),
                springref: f(&l.springref),
                joint: l.joint,
                range: l.range.clone(),
                offset: l.offset.as_ref().map(|o| Offset {
                    angle: o.angle.clone(),
                    cos: f(&o.cos),
                    sin: f(&o.sin),
                }),
                reversed: l.reversed,
            })
            .collect();
        let gravity = (f(&self.gravity.0), f(&self.gravity.1));
        let payload = self.payload.as_ref().map(|p| PayloadSpec {
            mass: f(&p.mass),
            inertia: f(&p.inertia),
            com: (f(&p.com.0), f(&p.com.1)),
        });
        ArmSpec {
            links,
            gravity,
            payload,
        }
    }

    /// Gravity of magnitude `g` along -y, when gravity's x component is zero: what the
    /// closed forms that assume it (the regressor's energy elimination) need.
    #[must_use]
    pub fn gravity_down(&self) -> Option<C>
    where
        C: Coefficient,
    {
        self.gravity.0.is_zero().then(|| -self.gravity.1.clone())
    }

    /// Whether every joint turns (slides) the standard way with no offset: the convention the
    /// pairwise metric, the composite bodies and the closed forms are written in.
    #[must_use]
    pub fn plain(&self) -> bool {
        self.links.iter().all(|l| l.offset.is_none() && !l.reversed)
    }

    /// Whether every joint is revolute (the paper's arms).
    #[must_use]
    pub fn all_revolute(&self) -> bool {
        self.links.iter().all(|l| l.joint == JointKind::Revolute)
    }

    /// The same arm with joint `i` prismatic where bit `i` of `pattern` is set: the tests'
    /// way to run one check over every mix of joint kinds.
    #[cfg(test)]
    pub(crate) fn with_prismatic(mut self, pattern: u32) -> Self {
        for (i, l) in self.links.iter_mut().enumerate() {
            if pattern >> i & 1 == 1 {
                l.joint = JointKind::Prismatic;
            }
        }
        self
    }
}
