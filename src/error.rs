use core::fmt;

#[cfg(not(feature = "std"))]
use num_traits::Float as _;

/// What went wrong in a method that can fail: inverse kinematics, inverse statics, checked dynamics.
///
/// The enum is `#[non_exhaustive]`: match on the variants you handle and keep a `_` arm.
///
/// Its `Display` rounds every number to six significant digits, so that a distance computed as
/// `0.0009999999999998899` reads `0.001`; the fields keep the exact values.
///
/// # Example
/// ```
/// use planar_arm::ArmError;
///
/// let e = ArmError::Unreachable {
///     target: [2.0, 0.0],
///     orientation: None,
///     radius: 2.0,
///     inner: 0.0,
///     outer: 1.9990000000000001,
///     distance: 0.0009999999999998899,
/// };
/// assert_eq!(
///     e.to_string(),
///     "target (2, 0) is 0.001 beyond the reachable annulus 0 ..= 1.999 (it lies 2 from the base)"
/// );
/// ```
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ArmError {
    /// An input held NaN or an infinity, or (argument `"result"`) finite input gave a result
    /// that overflowed.
    NonFinite {
        /// Which argument: `"q"`, `"target"`, `"tau"`, ..., or `"result"`.
        argument: &'static str,
    },
    /// The target lies outside the work-space.
    ///
    /// For a position target, `radius` is the target's distance from the base and the annulus
    /// is the arm's [`Workspace`](crate::kinematics::Workspace). For a pose target (the tip at
    /// a point with the last link at an angle), the point that must lie in an annulus is the
    /// wrist, the last joint, at `target - l_N (cos phi, sin phi)`: `radius` is the wrist's
    /// distance from the base and the annulus the one the links before the last reach.
    ///
    /// For arms with prismatic joints or joint ranges, the region reached need not be an
    /// annulus: `inner ..= outer` are then radii about the base that bound it, and a target may
    /// lie between them and still be out of reach, `distance` metres outside the region. A
    /// target that joint values outside the ranges would reach is
    /// [`BeyondJointRange`](Self::BeyondJointRange) instead.
    Unreachable {
        /// The tip position the caller asked for, `[x, y]`.
        target: [f64; 2],
        /// The absolute angle of the last link the caller asked for (radians), `None` for a
        /// position target.
        orientation: Option<f64>,
        /// Distance from the base to the point that must be reached: the target, or for a pose
        /// target the wrist point.
        radius: f64,
        /// Inner radius of the annulus that can be reached.
        inner: f64,
        /// Outer radius of the annulus that can be reached.
        outer: f64,
        /// How far outside the annulus the point is, or for a target that joint ranges exclude
        /// how far outside its range the nearest solution's joint is (always > 0).
        distance: f64,
    },
    /// The target lies where the links would reach it with free joints, but every solution
    /// puts some joint outside its `range`.
    ///
    /// `joint` and `excess` describe the solution that comes nearest to the ranges: the joint
    /// that lies farthest outside its range in that solution, and by how much, in the joint's
    /// own unit (radians for a hinge, metres for a slide).
    BeyondJointRange {
        /// The joint, 0-based as in `q[joint]`.
        joint: usize,
        /// Its kind, which gives the unit of `excess`.
        kind: crate::Joint,
        /// How far outside its range that joint lies (always > 0): radians for
        /// [`Joint::Revolute`](crate::Joint::Revolute), metres for
        /// [`Joint::Prismatic`](crate::Joint::Prismatic).
        excess: f64,
    },
    /// A spatial arm cannot place the point (or, for the arms whose last axes do not all meet,
    /// the direction) its closed-form inverse kinematics turns on where the target needs it:
    /// `what` names it ("the wrist centre", "the elbow's annulus", "the tool axis"), and
    /// `distance` says by how much, in `unit` (`"m"` or `"rad"`).
    OutOfReach {
        /// The tool position asked for, `[x, y, z]`.
        target: [f64; 3],
        /// What cannot be placed.
        what: &'static str,
        /// By how much (always > 0).
        distance: f64,
        /// `"m"` for a point, `"rad"` for a direction.
        unit: &'static str,
    },
    /// The arm's geometry has no closed form for what was asked: `what` says which (a spatial
    /// arm outside the classes of [`SpatialIk`](crate::spatial::SpatialIk), a wrench of an arm
    /// whose `J^T w = tau` is not square).
    NoClosedForm {
        /// What has none, and what to use instead.
        what: &'static str,
    },
    /// The configuration is singular (or too close to it) for the requested inverse.
    Singular {
        /// The quantity that vanishes at the singularity, for example `l1 l2 sin q2`.
        measure: f64,
        /// The documented threshold below which `|measure|` counts as singular.
        threshold: f64,
    },
    /// A parameter of the arm, or an option, is outside its range (see
    /// [`Model::check`](crate::Model::check)).
    OutOfRange {
        /// Which value: `"mass"`, `"length"`, `"payload mass"`, `"joint limits"`, ...
        what: &'static str,
        /// The link or joint it belongs to (0-based), or `None` for the payload and gravity.
        link: Option<usize>,
        /// The value found.
        value: f64,
    },
    /// An iterative solver did not reach the requested tolerance.
    NoConvergence {
        /// Iterations spent.
        iterations: usize,
        /// Residual norm at the end.
        residual: f64,
    },
    /// No tip wrench balances the joint torques: for an arm of more than three links, `J^T w =
    /// tau` has more equations than unknowns, and the part of `tau` outside the range of `J^T`
    /// (torques that move the arm's joints without moving its tip) is too large.
    Unbalanced {
        /// The norm of the torques no tip wrench balances, N m.
        residual: f64,
        /// The tolerance it exceeds, N m.
        tolerance: f64,
    },
    /// [`lqr`](crate::lqr) or [`dlqr`](crate::dlqr) has no stabilising gain: a mode of `A` on
    /// or beyond the stability boundary (`Re s >= 0`, or `|z| >= 1` in discrete time) is not
    /// moved by the input (`(A, B)` is not stabilisable) or not weighed by the cost (`(Q, A)`
    /// is not detectable).
    NotStabilizable {
        /// The mode's eigenvalue of `A`, `[re, im]` (its conjugate is one too).
        eigenvalue: [f64; 2],
        /// Whether the pair is discrete-time ([`dlqr`](crate::dlqr)).
        discrete: bool,
        /// `"B"`: no input moves the mode; `"Q"`: the cost does not see it.
        missed_by: &'static str,
        /// The relative Popov-Belevitch-Hautus measure: the smallest singular value of
        /// `[A - s I, B]` (or `[A - s I; C]`, `C^T C = Q`) over its norm, `B` and `C` scaled to
        /// the norm of `A - s I`; zero for an exact miss, below `1e-8` here.
        measure: f64,
    },
}

/// `1st`, `2nd`, `3rd`, `4th`, ..., `11th`, `12th`, `21st`: the position of a link or joint from
/// the base, so that a message can give both the 0-based index and the count a person uses.
struct Ordinal(usize);

impl fmt::Display for Ordinal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let n = self.0;
        let suffix = match (n % 10, n % 100) {
            (_, 11..=13) => "th",
            (1, _) => "st",
            (2, _) => "nd",
            (3, _) => "rd",
            _ => "th",
        };
        write!(f, "{n}{suffix}")
    }
}

/// A number to six significant digits, trailing zeros dropped: `0.001`, `1.5`, `2.5e-12`.
struct Rounded(f64);

impl fmt::Display for Rounded {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if !x.is_finite() || x == 0.0 {
            // `0` rather than `-0`, `inf` and `NaN` as Rust spells them.
            return write!(f, "{}", if x == 0.0 { 0.0 } else { x });
        }
        let mut buffer = Buffer::default();
        let magnitude = x.abs();
        if (1e-4..1e15).contains(&magnitude) {
            // Decimal places that leave six significant digits.
            let mut decimals = 5_usize;
            let mut p = 1.0;
            while magnitude < p && decimals < 9 {
                p /= 10.0;
                decimals += 1;
            }
            let mut p = 10.0;
            while magnitude >= p && decimals > 0 {
                p *= 10.0;
                decimals -= 1;
            }
            fmt::write(&mut buffer, format_args!("{x:.decimals$}"))?;
            f.write_str(trim_fraction(buffer.as_str()))
        } else {
            fmt::write(&mut buffer, format_args!("{x:.5e}"))?;
            let text = buffer.as_str();
            let (mantissa, exponent) = text.split_at(text.find('e').unwrap_or(text.len()));
            f.write_str(trim_fraction(mantissa))?;
            f.write_str(exponent)
        }
    }
}

/// `1.500000` to `1.5`, `2.000` to `2`; text without a point is left alone.
fn trim_fraction(text: &str) -> &str {
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.')
    } else {
        text
    }
}

/// Room for one number formatted by [`Rounded`] (at most 24 characters).
struct Buffer {
    bytes: [u8; 40],
    len: usize,
}

impl Default for Buffer {
    fn default() -> Self {
        Self {
            bytes: [0; 40],
            len: 0,
        }
    }
}

impl Buffer {
    fn as_str(&self) -> &str {
        // Only `fmt::Write::write_str` fills it, with whole `str`s.
        core::str::from_utf8(&self.bytes[..self.len]).unwrap_or("")
    }
}

impl fmt::Write for Buffer {
    fn write_str(&mut self, s: &str) -> fmt::Result {
        let end = self.len + s.len();
        if end > self.bytes.len() {
            return Err(fmt::Error);
        }
        self.bytes[self.len..end].copy_from_slice(s.as_bytes());
        self.len = end;
        Ok(())
    }
}

impl fmt::Display for ArmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let r = Rounded;
        match *self {
            Self::NonFinite { argument: "result" } => {
                write!(f, "the result overflowed to an infinity (or NaN) for finite input")
            }
            Self::NonFinite { argument } => {
                write!(f, "argument `{argument}` holds NaN or an infinity")
            }
            Self::Unreachable {
                target: [x, y],
                orientation,
                radius,
                inner,
                outer,
                distance,
            } => {
                // Past the annulus when `distance` is the distance to it; otherwise the target
                // lies between the bounding radii (or on them, to rounding) and `distance` is
                // how far outside the region within them it lies.
                let annular = (radius - outer).max(inner - radius).max(0.0);
                let scale = outer.abs().max(radius.abs()).max(f64::MIN_POSITIVE);
                let past_annulus = (distance - annular).abs() <= 1e-9 * scale;
                let side = if radius > outer { "beyond" } else { "inside the hole of" };
                match (orientation, past_annulus) {
                    (None, false) => write!(
                        f,
                        "target ({}, {}) lies {} from the base, within the radii {} ..= {}, but {} m \
                         outside the region the joints reach",
                        r(x), r(y), r(radius), r(inner), r(outer), r(distance)
                    ),
                    (Some(phi), false) => write!(
                        f,
                        "target ({}, {}) with the last link at {} rad is unreachable: its wrist point lies \
                         {} from the base, within the radii {} ..= {}, but {} m outside the region the \
                         links before the last reach",
                        r(x), r(y), r(phi), r(radius), r(inner), r(outer), r(distance)
                    ),
                    (None, true) => write!(
                        f,
                        "target ({}, {}) is {} {side} the reachable annulus {} ..= {} (it lies {} from the base)",
                        r(x), r(y), r(distance), r(inner), r(outer), r(radius)
                    ),
                    (Some(phi), true) => write!(
                        f,
                        "target ({}, {}) with the last link at {} rad is unreachable: its wrist point lies {} \
                         from the base, {} {side} the annulus {} ..= {} the links before the last reach",
                        r(x), r(y), r(phi), r(radius), r(distance), r(inner), r(outer)
                    ),
                }
            }
            Self::BeyondJointRange {
                joint,
                kind,
                excess,
            } => {
                let (what, unit) = match kind {
                    crate::Joint::Revolute => ("hinge", "rad"),
                    crate::Joint::Prismatic => ("slide", "m"),
                };
                write!(
                    f,
                    "the target is out of reach within the joint ranges: the nearest solution puts \
                     q[{joint}] (the {} joint, a {what}) {} {unit} outside its range",
                    Ordinal(joint + 1),
                    r(excess)
                )
            }
            Self::Singular { measure, threshold } if measure.is_nan() => write!(
                f,
                "singular configuration: the measure of singularity is not a number (threshold {})",
                r(threshold)
            ),
            Self::OutOfReach {
                target: [x, y, z],
                what,
                distance,
                unit,
            } => write!(
                f,
                "target at ({}, {}, {}) is out of reach: {what} misses by {} {unit}",
                r(x),
                r(y),
                r(z),
                r(distance)
            ),
            Self::NoClosedForm { what } => write!(f, "no closed form: {what}"),
            Self::Singular {
                measure: 0.0,
                threshold,
            } => write!(
                f,
                "singular configuration: the measure of singularity is exactly 0 (threshold {})",
                r(threshold)
            ),
            Self::Singular { measure, threshold } => write!(
                f,
                "singular configuration: |{}| is at most the threshold {}",
                r(measure),
                r(threshold)
            ),
            Self::OutOfRange {
                what: "mass matrix",
                link: Some(i),
                value,
            } => write!(
                f,
                "links[{i}] (the {} link): the mass matrix is singular at this joint (pivot {} of its \
                 diagonal entry): the joint moves (almost) no mass and turns no inertia; give the \
                 link inertia or a centre of mass off its axis, or add armature",
                Ordinal(i + 1),
                r(value)
            ),
            Self::OutOfRange { what, link, value } => match link {
                Some(i) => write!(
                    f,
                    "links[{i}] (the {} link): {what} = {} is out of range",
                    Ordinal(i + 1),
                    r(value)
                ),
                None => write!(f, "{what} = {} is out of range", r(value)),
            },
            Self::NoConvergence {
                iterations,
                residual,
            } => write!(
                f,
                "no convergence after {iterations} iterations (residual {})",
                r(residual)
            ),
            Self::Unbalanced {
                residual,
                tolerance,
            } => write!(
                f,
                "no tip wrench balances these joint torques: {} N m of them move the joints but not \
                 the tip (tolerance {})",
                r(residual),
                r(tolerance)
            ),
            Self::NotStabilizable {
                eigenvalue: [re, im],
                discrete,
                missed_by,
                measure,
            } => {
                write!(f, "no stabilising LQR gain: the mode at eigenvalue {}", r(re))?;
                if im != 0.0 {
                    write!(f, " +- {}i", r(im.abs()))?;
                }
                if discrete {
                    write!(f, " (|z| = {} >= 1)", r(re.hypot(im)))?;
                } else {
                    write!(f, " (Re s = {} >= 0)", r(re))?;
                }
                if missed_by == "Q" {
                    write!(
                        f,
                        " is not weighed by Q, so (Q, A) is not detectable; give it weight in Q"
                    )?;
                } else {
                    write!(
                        f,
                        " is not moved by any input, so (A, B) is not stabilisable"
                    )?;
                }
                write!(f, " (PBH measure {})", r(measure))
            }
        }
    }
}

impl core::error::Error for ArmError {}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_print_to_six_significant_digits() {
        let cases = [
            (0.0009999999999998899, "0.001"),
            (1.5, "1.5"),
            (2.0, "2"),
            (-0.25, "-0.25"),
            (123456.789, "123457"),
            (1.0 / 3.0, "0.333333"),
            (2.5e-12, "2.5e-12"),
            (-3.0e20, "-3e20"),
            (1e-4, "0.0001"),
            (0.0, "0"),
            (-0.0, "0"),
            (f64::INFINITY, "inf"),
            (f64::NAN, "NaN"),
            (f64::MAX, "1.79769e308"),
            (f64::MIN_POSITIVE * 1e-10, "2.22507e-318"),
        ];
        for (x, text) in cases {
            assert_eq!(Rounded(x).to_string(), text, "{x:e}");
        }
    }

    #[test]
    fn messages_name_the_target() {
        let e = ArmError::Unreachable {
            target: [1.2, 0.4],
            orientation: Some(0.3),
            radius: 2.0000000000000004,
            inner: 0.2,
            outer: 1.8,
            distance: 0.20000000000000018,
        };
        assert_eq!(
            e.to_string(),
            "target (1.2, 0.4) with the last link at 0.3 rad is unreachable: its wrist point lies 2 \
             from the base, 0.2 beyond the annulus 0.2 ..= 1.8 the links before the last reach"
        );
        let hole = ArmError::Unreachable {
            target: [0.1, 0.0],
            orientation: None,
            radius: 0.1,
            inner: 0.7,
            outer: 2.3,
            distance: 0.6,
        };
        assert!(hole
            .to_string()
            .contains("0.6 inside the hole of the reachable annulus 0.7"));
        let ranged = ArmError::Unreachable {
            target: [0.5, -0.5],
            orientation: None,
            radius: 0.75,
            inner: 0.0,
            outer: 1.3,
            distance: 0.5,
        };
        assert_eq!(
            ranged.to_string(),
            "target (0.5, -0.5) lies 0.75 from the base, within the radii 0 ..= 1.3, but 0.5 m \
             outside the region the joints reach"
        );
        // A wrist on the outer radius (to rounding) and 0.91 outside the region within it: not
        // "0.91 beyond the annulus".
        let edge = ArmError::Unreachable {
            target: [1.0, 1.5],
            orientation: Some(0.5),
            radius: 1.8000000000000003,
            inner: 0.0,
            outer: 1.8,
            distance: 0.91,
        };
        let text = edge.to_string();
        assert!(
            text.contains("within the radii 0 ..= 1.8, but 0.91 m outside"),
            "{text}"
        );
        let joint = ArmError::BeyondJointRange {
            joint: 1,
            kind: crate::Joint::Revolute,
            excess: 0.2518 + 3e-17,
        };
        assert_eq!(
            joint.to_string(),
            "the target is out of reach within the joint ranges: the nearest solution puts q[1] \
             (the 2nd joint, a hinge) 0.2518 rad outside its range"
        );
        let slide = ArmError::BeyondJointRange {
            joint: 0,
            kind: crate::Joint::Prismatic,
            excess: 0.2,
        };
        assert!(slide
            .to_string()
            .ends_with("q[0] (the 1st joint, a slide) 0.2 m outside its range"));
        for (measure, threshold, text) in [
            (
                0.0,
                0.0,
                "singular configuration: the measure of singularity is exactly 0 (threshold 0)",
            ),
            (
                1e-13,
                1e-12,
                "singular configuration: |1e-13| is at most the threshold 1e-12",
            ),
        ] {
            assert_eq!(ArmError::Singular { measure, threshold }.to_string(), text);
        }
        let link = ArmError::OutOfRange {
            what: "mass",
            link: Some(1),
            value: -2.0,
        };
        assert_eq!(
            link.to_string(),
            "links[1] (the 2nd link): mass = -2 is out of range"
        );
        let ordinals: Vec<String> = [1, 2, 3, 4, 11, 12, 13, 21, 22, 101, 111]
            .iter()
            .map(|&n| Ordinal(n).to_string())
            .collect();
        assert_eq!(
            ordinals,
            [
                "1st", "2nd", "3rd", "4th", "11th", "12th", "13th", "21st", "22nd", "101st",
                "111th"
            ]
        );
        let overflow = ArmError::NonFinite { argument: "result" };
        assert!(overflow.to_string().contains("overflowed"));
    }

    #[test]
    fn unstabilisable_modes_are_named_with_their_distance_past_the_boundary() {
        let unseen = ArmError::NotStabilizable {
            eigenvalue: [0.25, -1.5],
            discrete: false,
            missed_by: "Q",
            measure: 3.0000000000000004e-17,
        };
        assert_eq!(
            unseen.to_string(),
            "no stabilising LQR gain: the mode at eigenvalue 0.25 +- 1.5i (Re s = 0.25 >= 0) is \
             not weighed by Q, so (Q, A) is not detectable; give it weight in Q (PBH measure 3e-17)"
        );
        let unmoved = ArmError::NotStabilizable {
            eigenvalue: [-0.6, 0.8],
            discrete: true,
            missed_by: "B",
            measure: 0.0,
        };
        assert!(unmoved
            .to_string()
            .contains("eigenvalue -0.6 +- 0.8i (|z| = 1 >= 1) is not moved by any input"));
    }
}
