use core::fmt;

use crate::ArmError;

/// What went wrong in a simulation, a trajectory or a controller's construction.
///
/// The enum is `#[non_exhaustive]`: match on the variants you handle and keep a `_` arm.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum SimError {
    /// A step, period, duration or time that must be a positive finite number is not, or
    /// times that must increase do not.
    BadArgument {
        /// Which argument: `"dt"`, `"control period"`, `"duration"`, `"times"`, ...
        argument: &'static str,
        /// The value found.
        value: f64,
    },
    /// A state, a torque or an initial condition holds NaN or an infinity.
    NonFinite {
        /// Which quantity: `"q"`, `"qd"`, `"tau"` (the controller's output), `"q0"`, ...
        argument: &'static str,
        /// The simulated time at which it was found, s (NaN outside a simulation loop).
        t: f64,
    },
    /// The implicit step of a variational integrator did not converge: the step is too large
    /// for its fixed-point iteration (see [`VariationalMidpoint`](super::VariationalMidpoint)).
    NoConvergence {
        /// Iterations spent.
        iterations: u32,
        /// The last change of the midpoint velocity, rad/s.
        change: f64,
    },
    /// The arm's kinematics failed (inverse kinematics of a tip path, for example).
    Arm(ArmError),
}

impl SimError {
    /// The same error, with the simulated time `t` filled in where it has one.
    pub(crate) fn at(self, t: f64) -> Self {
        match self {
            Self::NonFinite { argument, .. } => Self::NonFinite { argument, t },
            other => other,
        }
    }
}

impl From<ArmError> for SimError {
    fn from(e: ArmError) -> Self {
        Self::Arm(e)
    }
}

impl fmt::Display for SimError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::BadArgument { argument, value } => {
                write!(f, "`{argument}` = {value} is out of range")
            }
            Self::NonFinite { argument, t } if t.is_nan() => {
                write!(f, "`{argument}` holds NaN or an infinity")
            }
            Self::NonFinite { argument, t } => {
                write!(f, "`{argument}` holds NaN or an infinity at t = {t} s")
            }
            Self::NoConvergence { iterations, change } => write!(
                f,
                "the implicit step did not converge in {iterations} iterations (last change {change:.3e} rad/s); use a smaller step"
            ),
            Self::Arm(e) => write!(f, "{e}"),
        }
    }
}

impl core::error::Error for SimError {
    fn source(&self) -> Option<&(dyn core::error::Error + 'static)> {
        match self {
            Self::Arm(e) => Some(e),
            _ => None,
        }
    }
}

/// `Ok(())` when every entry of `v` is finite.
pub(crate) fn finite<const N: usize>(
    v: &nalgebra::SVector<f64, N>,
    argument: &'static str,
) -> Result<(), SimError> {
    if v.iter().all(|x| x.is_finite()) {
        Ok(())
    } else {
        Err(SimError::NonFinite {
            argument,
            t: f64::NAN,
        })
    }
}

/// `Ok(x)` when `x` is positive and finite.
pub(crate) fn positive(x: f64, argument: &'static str) -> Result<f64, SimError> {
    if x > 0.0 && x.is_finite() {
        Ok(x)
    } else {
        Err(SimError::BadArgument { argument, value: x })
    }
}
