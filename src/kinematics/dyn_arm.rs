//! A dyn-compatible view of [`PlanarArm`], so that different arms of the same `N` can share a
//! `Vec<Box<dyn DynArm<N>>>`.

use nalgebra::{Isometry2, Point2, SMatrix, SVector, Vector2};

use super::{DlsOptions, IkTarget, Skeleton, Workspace};
use crate::{ArmError, Link, Model, PlanarArm};

/// Every [`PlanarArm<N>`] behind one trait object: `Box<dyn DynArm<N>>`, `&dyn DynArm<N>`.
///
/// `PlanarArm` itself cannot be a trait object: its dynamics are generic over the scalar
/// ([`Real`](crate::Real)) and it has an associated constant ([`PlanarArm::EXACT`]) and type.
/// `DynArm<N>` is implemented for every `PlanarArm<N>` and offers the `f64` methods under the
/// same names on `dyn DynArm<N>` (also `+ Send` and `+ Send + Sync`), so code written for one
/// concrete arm reads the same for a boxed one. You never implement it, nor import it to call
/// its methods; its own trait methods are hidden, named so that they never make a concrete
/// arm's `PlanarArm` calls ambiguous where the trait is in scope.
///
/// The alternative when the set of arms is closed is an enum with one variant per arm type and
/// a `match` in each method: no allocation and the generic methods stay available.
///
/// # Example
/// ```
/// use planar_arm::kinematics::DynArm;
/// use planar_arm::prelude::*;
///
/// #[derive(PlanarArm, Default)]
/// struct Light {
///     #[arm(length = 1, mass = 1)] upper: Revolute,
///     #[arm(length = 1, mass = 1)] fore: Revolute,
/// }
/// #[derive(PlanarArm, Default)]
/// #[arm(payload = self.load)]
/// struct Loaded {
///     #[arm(length = 1, mass = 2)] upper: Revolute,
///     #[arm(length = 0.5, mass = 1)] fore: Revolute,
///     load: f64,
/// }
///
/// let arms: Vec<Box<dyn DynArm<2>>> = vec![
///     Box::new(Light::default()),
///     Box::new(Loaded { load: 1.5, ..Loaded::default() }),
/// ];
/// let q = Vector2::new(0.3, 0.4);
/// for arm in &arms {
///     // Holding still against gravity takes exactly the gravity torques.
///     let tau = arm.inverse_dynamics(&q, &Vector2::zeros(), &Vector2::zeros());
///     assert!((tau - arm.gravity(&q)).norm() < 1e-12);
///     let qdd = arm.forward_dynamics(&q, &Vector2::zeros(), &tau);
///     assert!(qdd.norm() < 1e-9);
/// }
/// // The boxed arms are still the concrete ones: the same numbers as a direct call.
/// let light = Light::default();
/// assert_eq!(arms[0].mass_matrix(&q), light.mass_matrix(&q));
/// assert_eq!(arms[1].model().payload.mass, 1.5);
/// assert_eq!(arms[1].workspace().outer_radius(), 1.5);
/// ```
pub trait DynArm<const N: usize> {
    #[doc(hidden)]
    fn __dyn_model(&self) -> Model<N>;
    #[doc(hidden)]
    fn __dyn_mass_matrix(&self, q: &SVector<f64, N>) -> SMatrix<f64, N, N>;
    #[doc(hidden)]
    fn __dyn_coriolis(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N>;
    #[doc(hidden)]
    fn __dyn_gravity(&self, q: &SVector<f64, N>) -> SVector<f64, N>;
    #[doc(hidden)]
    fn __dyn_friction(&self, qd: &SVector<f64, N>) -> SVector<f64, N>;
    #[doc(hidden)]
    fn __dyn_bias(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N>;
    #[doc(hidden)]
    fn __dyn_inverse_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> SVector<f64, N>;
    #[doc(hidden)]
    fn __dyn_forward_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> SVector<f64, N>;
    #[doc(hidden)]
    fn __dyn_try_forward_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<SVector<f64, N>, ArmError>;
    #[doc(hidden)]
    fn __dyn_kinetic_energy(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> f64;
    #[doc(hidden)]
    fn __dyn_potential_energy(&self, q: &SVector<f64, N>) -> f64;
    #[doc(hidden)]
    fn __dyn_tip_pose(&self, q: &SVector<f64, N>) -> Isometry2<f64>;
    #[doc(hidden)]
    fn __dyn_jacobian(&self, q: &SVector<f64, N>) -> SMatrix<f64, 3, N>;
    #[doc(hidden)]
    fn __dyn_joint_positions(&self, q: &SVector<f64, N>) -> [Point2<f64>; N];
    #[doc(hidden)]
    fn __dyn_joint_torques(
        &self,
        q: &SVector<f64, N>,
        force: &Vector2<f64>,
        torque: f64,
    ) -> SVector<f64, N>;
    #[doc(hidden)]
    fn __dyn_inverse_kinematics_near(
        &self,
        target: &IkTarget,
        seed: &SVector<f64, N>,
        options: &DlsOptions<N>,
    ) -> Result<SVector<f64, N>, ArmError>;
}

impl<A: PlanarArm<N>, const N: usize> DynArm<N> for A {
    fn __dyn_model(&self) -> Model<N> {
        self.model()
    }
    fn __dyn_mass_matrix(&self, q: &SVector<f64, N>) -> SMatrix<f64, N, N> {
        self.mass_matrix(q)
    }
    fn __dyn_coriolis(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
        self.coriolis(q, qd)
    }
    fn __dyn_gravity(&self, q: &SVector<f64, N>) -> SVector<f64, N> {
        self.gravity(q)
    }
    fn __dyn_friction(&self, qd: &SVector<f64, N>) -> SVector<f64, N> {
        self.friction(qd)
    }
    fn __dyn_bias(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
        self.bias(q, qd)
    }
    fn __dyn_inverse_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        qdd: &SVector<f64, N>,
    ) -> SVector<f64, N> {
        self.inverse_dynamics(q, qd, qdd)
    }
    fn __dyn_forward_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> SVector<f64, N> {
        self.forward_dynamics(q, qd, tau)
    }
    fn __dyn_try_forward_dynamics(
        &self,
        q: &SVector<f64, N>,
        qd: &SVector<f64, N>,
        tau: &SVector<f64, N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        self.try_forward_dynamics(q, qd, tau)
    }
    fn __dyn_kinetic_energy(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> f64 {
        self.kinetic_energy(q, qd)
    }
    fn __dyn_potential_energy(&self, q: &SVector<f64, N>) -> f64 {
        self.potential_energy(q)
    }
    fn __dyn_tip_pose(&self, q: &SVector<f64, N>) -> Isometry2<f64> {
        self.tip_pose(q)
    }
    fn __dyn_jacobian(&self, q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
        self.jacobian(q)
    }
    fn __dyn_joint_positions(&self, q: &SVector<f64, N>) -> [Point2<f64>; N] {
        self.joint_positions(q)
    }
    fn __dyn_joint_torques(
        &self,
        q: &SVector<f64, N>,
        force: &Vector2<f64>,
        torque: f64,
    ) -> SVector<f64, N> {
        self.joint_torques(q, force, torque)
    }
    fn __dyn_inverse_kinematics_near(
        &self,
        target: &IkTarget,
        seed: &SVector<f64, N>,
        options: &DlsOptions<N>,
    ) -> Result<SVector<f64, N>, ArmError> {
        super::inverse_kinematics_near(self, target, seed, options)
    }
}

macro_rules! dyn_methods {
    ($($bounds:tt)*) => {
        /// The `f64` methods of [`PlanarArm`], each documented there.
        impl<const N: usize> dyn DynArm<N> $($bounds)* + '_ {
            /// [`PlanarArm::model`].
            pub fn model(&self) -> Model<N> {
                self.__dyn_model()
            }
            /// [`PlanarArm::links`].
            pub fn links(&self) -> [Link; N] {
                self.__dyn_model().links
            }
            /// [`Dynamics::mass_matrix`](crate::Dynamics::mass_matrix).
            pub fn mass_matrix(&self, q: &SVector<f64, N>) -> SMatrix<f64, N, N> {
                self.__dyn_mass_matrix(q)
            }
            /// [`Dynamics::coriolis`](crate::Dynamics::coriolis).
            pub fn coriolis(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
                self.__dyn_coriolis(q, qd)
            }
            /// [`Dynamics::gravity`](crate::Dynamics::gravity).
            pub fn gravity(&self, q: &SVector<f64, N>) -> SVector<f64, N> {
                self.__dyn_gravity(q)
            }
            /// [`Dynamics::friction`](crate::Dynamics::friction).
            pub fn friction(&self, qd: &SVector<f64, N>) -> SVector<f64, N> {
                self.__dyn_friction(qd)
            }
            /// [`Dynamics::bias`](crate::Dynamics::bias).
            pub fn bias(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> SVector<f64, N> {
                self.__dyn_bias(q, qd)
            }
            /// [`Dynamics::inverse_dynamics`](crate::Dynamics::inverse_dynamics).
            pub fn inverse_dynamics(
                &self,
                q: &SVector<f64, N>,
                qd: &SVector<f64, N>,
                qdd: &SVector<f64, N>,
            ) -> SVector<f64, N> {
                self.__dyn_inverse_dynamics(q, qd, qdd)
            }
            /// [`Dynamics::forward_dynamics`](crate::Dynamics::forward_dynamics).
            pub fn forward_dynamics(
                &self,
                q: &SVector<f64, N>,
                qd: &SVector<f64, N>,
                tau: &SVector<f64, N>,
            ) -> SVector<f64, N> {
                self.__dyn_forward_dynamics(q, qd, tau)
            }
            /// [`Dynamics::try_forward_dynamics`](crate::Dynamics::try_forward_dynamics).
            ///
            /// # Errors
            /// As there.
            pub fn try_forward_dynamics(
                &self,
                q: &SVector<f64, N>,
                qd: &SVector<f64, N>,
                tau: &SVector<f64, N>,
            ) -> Result<SVector<f64, N>, ArmError> {
                self.__dyn_try_forward_dynamics(q, qd, tau)
            }
            /// [`Dynamics::kinetic_energy`](crate::Dynamics::kinetic_energy).
            pub fn kinetic_energy(&self, q: &SVector<f64, N>, qd: &SVector<f64, N>) -> f64 {
                self.__dyn_kinetic_energy(q, qd)
            }
            /// [`Dynamics::potential_energy`](crate::Dynamics::potential_energy).
            pub fn potential_energy(&self, q: &SVector<f64, N>) -> f64 {
                self.__dyn_potential_energy(q)
            }
            /// [`PlanarArm::tip_pose`].
            pub fn tip_pose(&self, q: &SVector<f64, N>) -> Isometry2<f64> {
                self.__dyn_tip_pose(q)
            }
            /// [`PlanarArm::jacobian`].
            pub fn jacobian(&self, q: &SVector<f64, N>) -> SMatrix<f64, 3, N> {
                self.__dyn_jacobian(q)
            }
            /// [`PlanarArm::joint_positions`].
            pub fn joint_positions(&self, q: &SVector<f64, N>) -> [Point2<f64>; N] {
                self.__dyn_joint_positions(q)
            }
            /// Every joint and the tip, [`Skeleton`].
            pub fn skeleton(&self, q: &SVector<f64, N>) -> Skeleton<N> {
                Skeleton {
                    joints: self.__dyn_joint_positions(q),
                    tip: Point2::from(self.__dyn_tip_pose(q).translation.vector),
                }
            }
            /// [`PlanarArm::joint_torques`].
            pub fn joint_torques(
                &self,
                q: &SVector<f64, N>,
                force: &Vector2<f64>,
                torque: f64,
            ) -> SVector<f64, N> {
                self.__dyn_joint_torques(q, force, torque)
            }
            /// [`PlanarArm::workspace`].
            pub fn workspace(&self) -> Workspace {
                Workspace::of_links(&self.links())
            }
            /// [`PlanarArm::inverse_kinematics_near`].
            ///
            /// # Errors
            /// As there.
            pub fn inverse_kinematics_near(
                &self,
                target: &IkTarget,
                seed: &SVector<f64, N>,
                options: &DlsOptions<N>,
            ) -> Result<SVector<f64, N>, ArmError> {
                self.__dyn_inverse_kinematics_near(target, seed, options)
            }
        }
    };
}

dyn_methods!();
dyn_methods!(+ Send);
dyn_methods!(+ Send + Sync);
