//! Spatial (3-D) serial arms: joints in Denavit-Hartenberg or URDF form, their numeric
//! description, and closed-form inverse kinematics by decoupling the wrist.
//!
//! `#[derive(SpatialArm)]` reads one joint per field (`Revolute` or `Prismatic`) in one of
//! three conventions and generates [`SpatialArm`]: the tool and link poses, the geometric
//! Jacobian, statics and, for six-joint arms whose wrist decouples, every inverse-kinematics
//! solution in closed form; and [`Dynamics`](crate::Dynamics), the equations of motion planar
//! arms have, with the same names (the inverse dynamics by the recursive Newton-Euler
//! algorithm and the mass matrix by the composite-rigid-body algorithm, each unrolled at
//! compile time in the links' own frames), with a payload at the tool (`payload`,
//! `payload_com`, `payload_inertia(..)` on the struct) and `freeze`; and, for arms of exact
//! geometry, [`Identification`](crate::Identification): ten standard parameters per link in
//! Pinocchio's order and the exact base parameters. The crate page's "Three-dimensional arms"
//! works through the PUMA 560; `examples/puma.rs` draws its solutions,
//! `examples/puma_dynamics.rs` tracks a tool path and `examples/puma_identify.rs` identifies
//! its base parameters from noisy torques.
//!
//! An arm can also come from its model file, `#[arm(urdf = "..")]` or `#[arm(mjcf = "..")]`
//! with `base` and `tip`, read at compile time with `q` equal to MuJoCo's `qpos`; and any arm
//! goes back out with [`SpatialArm::to_mjcf`] and [`SpatialArm::to_urdf`] (the README's "Arms
//! from model files"; `examples/models.rs`).
//!
//! How the derive builds the code: each joint is `pre * motion(q) * post`, constant parts
//! around one rotation about (or slide along) the joint's axis. Multiplied out exactly, with
//! twists at multiples of `pi/2` folding to 0 and 1 and consecutive parallel axes collapsing
//! to sums of angles (`c23`), the tool pose's entries are trigonometric polynomials; the
//! derive emits, method by method, whichever is cheaper of those formulas and the product of
//! the transformations, as straight-line code with one batched sine-cosine call. A twist that
//! is not a rational multiple of `pi/2` keeps its cosine and sine as named constants
//! (`cos(0.3)`), exact as symbols in `EXACT` and rounded once to `f64` in the code; generic
//! rotations at every joint would multiply out exponentially, so past a budget the derive
//! keeps the product alone ([`SpatialDerivation`](crate::exact::SpatialDerivation)).
//!
//! The closed forms ([`SpatialIk`]) are products of exponentials and the subproblems of
//! Paden and Kahan: with the wrist centre `c` fixed by the last three axes meeting (or the
//! tool axis by three parallel ones), the first three joints place `c` (an offset
//! polar-coordinate problem and two-link geometry, as the paper puts it) and the last three
//! turn the tool, up to eight solutions in all.

mod arm;
#[cfg(feature = "std")]
pub mod export;
mod ik;
mod joint;
mod model;
mod numeric;
mod statics;

pub use arm::SpatialArm;
pub use ik::{IkClass, IkSolutions, SpatialIk};
pub use joint::JointGeometry;
pub use model::{SpatialJoint, SpatialLink, SpatialModel};
/// `#[derive(SpatialArm)]`, beside the trait it implements.
pub use planar_arm_derive::SpatialArm;
