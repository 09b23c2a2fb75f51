use core::fmt;

/// What went wrong in a method that can fail: inverse kinematics, inverse statics, checked dynamics.
///
/// The enum is `#[non_exhaustive]`: match on the variants you handle and keep a `_` arm.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ArmError {
    /// An input held NaN or an infinity.
    NonFinite {
        /// Which argument: `"q"`, `"target"`, `"tau"`, ...
        argument: &'static str,
    },
    /// The target lies outside the work-space.
    Unreachable {
        /// Distance from the base (or from the wrist-circle centre) to the point that must be reached.
        radius: f64,
        /// Inner radius of the annulus that can be reached.
        inner: f64,
        /// Outer radius of the annulus that can be reached.
        outer: f64,
        /// How far outside the annulus the point is (always > 0).
        distance: f64,
    },
    /// The configuration is singular (or too close to it) for the requested inverse.
    Singular {
        /// The quantity that vanishes at the singularity, for example `l1 l2 sin q2`.
        measure: f64,
        /// The documented threshold below which `|measure|` counts as singular.
        threshold: f64,
    },
    /// A parameter of the arm is outside its physical range (see
    /// [`Model::check`](crate::Model::check)).
    OutOfRange {
        /// Which value: `"mass"`, `"length"`, `"payload mass"`, ...
        what: &'static str,
        /// The link it belongs to (0-based), or `None` for the payload and gravity.
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
}

impl fmt::Display for ArmError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NonFinite { argument } => {
                write!(f, "argument `{argument}` holds NaN or an infinity")
            }
            Self::Unreachable {
                radius,
                inner,
                outer,
                distance,
            } => write!(
                f,
                "target at radius {radius} is {distance} outside the reachable annulus {inner} ..= {outer}"
            ),
            Self::Singular { measure, threshold } => write!(
                f,
                "singular configuration: |{measure}| is below the threshold {threshold}"
            ),
            Self::OutOfRange { what, link, value } => match link {
                Some(i) => write!(f, "link {}: {what} = {value} is out of range", i + 1),
                None => write!(f, "{what} = {value} is out of range"),
            },
            Self::NoConvergence {
                iterations,
                residual,
            } => write!(
                f,
                "no convergence after {iterations} iterations (residual {residual})"
            ),
        }
    }
}

impl core::error::Error for ArmError {}
