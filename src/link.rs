/// The zero-sized marker type of a revolute link field in a `#[derive(PlanarArm)]` struct.
///
/// It carries no data: the link's parameters live in its `#[arm(...)]` attribute and are baked
/// into the generated code at compile time.
#[derive(Default, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Revolute;

/// The numeric parameters of one link, in SI units, as `f64`.
///
/// A derived arm exposes them as [`PlanarArm::LINKS`](crate::PlanarArm::LINKS) so that numeric code (the
/// [`reference`](crate::reference) implementations, a simulator) can model the same arm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Link {
    /// Distance from this link's joint to the next joint (or to the tip), metres.
    pub length: f64,
    /// Mass, kilograms.
    pub mass: f64,
    /// Moment of inertia about the link's centre of mass, kg m^2.
    pub inertia: f64,
    /// Distance of the centre of mass from this link's own joint, along the link, metres.
    pub com: f64,
}

impl Link {
    /// A uniform rod of the given length and mass: inertia `m l^2 / 12`, centre of mass at `l / 2`.
    #[must_use]
    pub fn rod(length: f64, mass: f64) -> Self {
        Self {
            length,
            mass,
            inertia: mass * length * length / 12.0,
            com: length / 2.0,
        }
    }
}
