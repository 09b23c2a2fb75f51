//! The kinematic tree a model file describes, in one form for both formats: bodies, each
//! hanging from its parent by a fixed pose and at most one joint that moves about or along an
//! axis through the body frame's origin.

use planar_arm_core::ring::Rational;
use planar_arm_core::JointKind;

use super::frame::{Inertial, Pose, Vec3};

/// Where an element is in its file, as `path:line:column`, for errors.
pub type Loc = String;

/// An error in a model file, its message starting with the file, line and column.
#[derive(Debug)]
pub struct FileError(pub String);

impl FileError {
    pub fn at(loc: &str, message: impl core::fmt::Display) -> Self {
        Self(format!("{loc}: {message}"))
    }
}

/// How a body moves relative to its parent.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)] // one per body, built once at compile time
pub enum Motion {
    /// Welded (URDF `fixed`, an MJCF body without joints).
    Fixed,
    /// A hinge or slide.
    Joint(Joint),
    /// A joint the chain cannot hold (a free or ball joint, a mimic joint, ...): refused on the
    /// chain, locked off it. The text says what it is.
    Unsupported(String),
}

/// A hinge or a slide.
#[derive(Clone, Debug)]
pub struct Joint {
    pub name: String,
    pub kind: JointKind,
    /// In the body's frame, not necessarily of unit length (not zero).
    pub axis: Vec3,
    pub range: Option<(Rational, Rational)>,
    pub armature: Rational,
    pub damping: Rational,
    pub frictionloss: Rational,
    /// A spring `stiffness (q - springref)`.
    pub stiffness: Rational,
    pub springref: Rational,
}

/// A body (URDF link, MJCF body).
#[derive(Clone, Debug)]
pub struct Body {
    pub name: String,
    pub parent: Option<usize>,
    /// The body's frame in its parent's when its joint is at zero; the joint's motion follows.
    pub origin: Pose,
    pub motion: Motion,
    /// Its mass properties in its own frame (`None`: massless).
    pub inertial: Option<Inertial>,
    pub loc: Loc,
}

/// Bodies, parents before children; body 0 is the root (the world, or URDF's root link).
#[derive(Clone, Debug, Default)]
pub struct Tree {
    pub bodies: Vec<Body>,
    /// Gravity the file states, if it does (MJCF's `<option gravity>`).
    pub gravity: Option<Vec3>,
    /// What the reader ignored, for a note in the generated docs.
    pub ignored: Vec<String>,
    /// Elements that couple joints (MJCF tendons and equality constraints): refused when they
    /// name a joint of the chain.
    pub couplings: Vec<Coupling>,
}

/// An element that ties joints together.
#[derive(Clone, Debug)]
pub struct Coupling {
    /// What it is, as "a fixed tendon".
    pub what: String,
    pub joints: Vec<String>,
    pub loc: Loc,
}

impl Tree {
    pub fn children(&self, b: usize) -> impl Iterator<Item = usize> + '_ {
        self.bodies
            .iter()
            .enumerate()
            .filter(move |(_, x)| x.parent == Some(b))
            .map(|(i, _)| i)
    }

    pub fn find(&self, name: &str) -> Option<usize> {
        self.bodies.iter().position(|b| b.name == name)
    }

    /// Whether any body in `b`'s subtree (`b` included) moves relative to its parent.
    pub fn moves(&self, b: usize) -> bool {
        !matches!(self.bodies[b].motion, Motion::Fixed) || self.children(b).any(|c| self.moves(c))
    }
}
