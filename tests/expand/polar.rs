#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::Dynamics<2> for Polar {
    /**The mass matrix M(q), derived exactly (symmetric; upper triangle shown). Joint angles `q`, rates `qd`, accelerations `qdd` (1-based in the formulas); `cK` and `sK...` are the cosine and sine of the sum of the joint angles named by the digits.

```text
M11 = 3/8 + 27/20 q2 + 3/2 q2^2
M12 = 0
M22 = 3/2
```


Cost: 3 multiplications, 2 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn mass_matrix<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 2, 2> {
        let _ = (&self.turret, &self.boom);
        let [_, __q2] = ::planar_arm::__private::unpack(__q);
        let __m11 = __T::from_f64(3.0 / 2.0) * __q2 * __q2 + __T::from_f64(3.0 / 8.0)
            + __T::from_f64(27.0 / 20.0) * __q2;
        let __m12 = __T::from_f64(0.0);
        let __m22 = __T::from_f64(3.0 / 2.0);
        ::planar_arm::__private::columns([[__m11, __m12], [__m12, __m22]])
    }
    /**The velocity-product torques c(q, qd).

```text
c1 = 27/20 qd1 qd2 + 3 qd1 qd2 q2
c2 = -27/40 qd1^2 - 3/2 qd1^2 q2
```


Cost: 8 multiplications, 3 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn coriolis<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 2> {
        let [_, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let __t1 = __qd1 * __qd2;
        let __cor1 = __T::from_f64(27.0 / 20.0) * __t1
            + __T::from_f64(3.0) * __t1 * __q2;
        let __t2 = __qd1 * __qd1;
        let __cor2 = -(__T::from_f64(27.0 / 40.0) * __t2)
            - __T::from_f64(3.0 / 2.0) * __q2 * __t2;
        ::planar_arm::__private::vector([__cor1, __cor2])
    }
    /**The Coriolis matrix from Christoffel symbols, C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k.

```text
C11 = 27/40 qd2 + 3/2 qd2 q2
C12 = 27/40 qd1 + 3/2 qd1 q2
C21 = -27/40 qd1 - 3/2 qd1 q2
C22 = 0
```


Cost: 6 multiplications, 4 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn coriolis_matrix<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 2, 2> {
        let [_, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let __cm11 = __T::from_f64(27.0 / 40.0) * __qd2
            + __T::from_f64(3.0 / 2.0) * __qd2 * __q2;
        let __t1 = __T::from_f64(27.0 / 40.0) * __qd1;
        let __t2 = __T::from_f64(3.0 / 2.0) * __q2 * __qd1;
        let __cm12 = __t1 + __t2;
        let __cm21 = -__t1 - __t2;
        let __cm22 = __T::from_f64(0.0);
        ::planar_arm::__private::columns([[__cm11, __cm21], [__cm12, __cm22]])
    }
    /**The gravity torques g(q) = dV/dq.

```text
g1 = 38259/4000 c1 + 2943/200 c1 q2
g2 = 2943/200 s1
```


Cost: 4 multiplications, 1 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn gravity<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 2> {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __g1 = __T::from_f64(38259.0 / 4000.0) * __c1
            + __T::from_f64(2943.0 / 200.0) * __c1 * __q2;
        let __g2 = __T::from_f64(2943.0 / 200.0) * __s1;
        ::planar_arm::__private::vector([__g1, __g2])
    }
    /**The joint friction torques f(qd): viscous `damping qd_i` plus Coulomb `frictionloss sign(qd_i)`, with sign(0) = 0 (MuJoCo's `damping` and `frictionloss`). The Coulomb term jumps at `qd_i = 0`.

```text
f1 = 0
f2 = 0
```


Cost: 0 multiplications, 0 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn friction<__T: ::planar_arm::Real>(
        &self,
        _: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 2> {
        let __f1 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__f1, __f1])
    }
    /**The bias h(q, qd) = c + g + f: every torque but the inertial one, so that `inverse_dynamics(q, qd, qdd) = mass_matrix(q) qdd + bias(q, qd)` (Pinocchio's `nonLinearEffects`, MuJoCo's `qfrc_bias` plus its passive joint friction).

Cost: 12 multiplications, 5 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn bias<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 2> {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __t1 = __qd1 * __qd2;
        let __h1 = __T::from_f64(38259.0 / 4000.0) * __c1
            + __T::from_f64(2943.0 / 200.0) * __c1 * __q2
            + __T::from_f64(27.0 / 20.0) * __t1 + __T::from_f64(3.0) * __q2 * __t1;
        let __t2 = __qd1 * __qd1;
        let __h2 = __T::from_f64(2943.0 / 200.0) * __s1
            - (__T::from_f64(27.0 / 40.0) * __t2
                + __T::from_f64(3.0 / 2.0) * __q2 * __t2);
        ::planar_arm::__private::vector([__h1, __h2])
    }
    /**M(q) and h(q, qd) = c + g + f in one pass, sharing the trigonometry and every common subexpression: what computed-torque and operational-space controllers need every cycle.

Cost: 15 multiplications, 7 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn mass_matrix_and_bias<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<__T, 2, 2>,
        ::planar_arm::nalgebra::SVector<__T, 2>,
    ) {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __m11 = __T::from_f64(3.0 / 2.0) * __q2 * __q2 + __T::from_f64(3.0 / 8.0)
            + __T::from_f64(27.0 / 20.0) * __q2;
        let __t1 = __qd1 * __qd2;
        let __h1 = __T::from_f64(38259.0 / 4000.0) * __c1
            + __q2 * __T::from_f64(2943.0 / 200.0) * __c1
            + __T::from_f64(27.0 / 20.0) * __t1 + __T::from_f64(3.0) * __q2 * __t1;
        let __t2 = __qd1 * __qd1;
        let __h2 = __T::from_f64(2943.0 / 200.0) * __s1
            - (__T::from_f64(27.0 / 40.0) * __t2
                + __T::from_f64(3.0 / 2.0) * __q2 * __t2);
        let __m12 = __T::from_f64(0.0);
        let __m22 = __T::from_f64(3.0 / 2.0);
        (
            ::planar_arm::__private::columns([[__m11, __m12], [__m12, __m22]]),
            ::planar_arm::__private::vector([__h1, __h2]),
        )
    }
    /**Lagrange's equation, tau_i = d/dt dL/dqd_i - dL/dq_i, expanded, plus the joint friction f(qd) (see `friction`).

```text
tau1 = 38259/4000 c1 + 3/8 qdd1 + 2943/200 c1 q2 + 27/20 qd1 qd2 + 27/20 qdd1 q2 + 3 qd1 qd2 q2 + 3/2 qdd1 q2^2
tau2 = 2943/200 s1 + 3/2 qdd2 - 27/40 qd1^2 - 3/2 qd1^2 q2
```


Cost: 18 multiplications, 9 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn inverse_dynamics<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qdd: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 2> {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let [__qdd1, __qdd2] = ::planar_arm::__private::unpack(__qdd);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __t1 = __qd1 * __qd2;
        let __t2 = __qdd1 * __q2;
        let __tau1 = __T::from_f64(38259.0 / 4000.0) * __c1
            + __T::from_f64(3.0 / 8.0) * __qdd1
            + __T::from_f64(2943.0 / 200.0) * __c1 * __q2
            + __T::from_f64(27.0 / 20.0) * __t1 + __T::from_f64(3.0 / 2.0) * __q2 * __t2
            + __T::from_f64(27.0 / 20.0) * __t2 + __T::from_f64(3.0) * __q2 * __t1;
        let __t3 = __qd1 * __qd1;
        let __tau2 = __T::from_f64(2943.0 / 200.0) * __s1
            + __T::from_f64(3.0 / 2.0) * __qdd2
            - (__T::from_f64(27.0 / 40.0) * __t3
                + __T::from_f64(3.0 / 2.0) * __q2 * __t3);
        ::planar_arm::__private::vector([__tau1, __tau2])
    }
    /**qdd = M^-1 (tau - c - g - f) in closed form (Cramer's rule, det = M11 M22 - M12^2 > 0).

Cost: 18 multiplications, 10 additions, 2 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn forward_dynamics<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 2>,
        __tau: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 2> {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let [__tau1, __tau2] = ::planar_arm::__private::unpack(__tau);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __t1 = __T::from_f64(3.0 / 2.0) * __q2 * __q2 + __T::from_f64(3.0 / 8.0)
            + __T::from_f64(27.0 / 20.0) * __q2;
        let __t2 = __qd1 * __qd2;
        let __t3 = __qd1 * __qd1;
        let __rhs1 = __tau1
            - (__T::from_f64(27.0 / 20.0) * __t2 + __T::from_f64(3.0) * __q2 * __t2)
            - (__T::from_f64(38259.0 / 4000.0) * __c1
                + __q2 * __T::from_f64(2943.0 / 200.0) * __c1);
        let __rhs2 = __tau2
            - (-(__T::from_f64(27.0 / 40.0) * __t3)
                - __T::from_f64(3.0 / 2.0) * __q2 * __t3)
            - __T::from_f64(2943.0 / 200.0) * __s1;
        let __det = __T::from_f64(3.0 / 2.0) * __t1;
        let __qdd1 = __T::from_f64(3.0 / 2.0) * __rhs1 / __det;
        let __qdd2 = __t1 * __rhs2 / __det;
        ::planar_arm::__private::vector([__qdd1, __qdd2])
    }
    /**The kinetic energy.

```text
T = 3/16 qd1^2 + 3/4 qd2^2 + 27/40 qd1^2 q2 + 3/4 qd1^2 q2^2
```


Cost: 8 multiplications, 3 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn kinetic_energy<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> __T {
        let [_, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let __t1 = __qd1 * __qd1;
        let __t2 = __t1 * __q2;
        let __kinetic = __T::from_f64(3.0 / 16.0) * __t1
            + __T::from_f64(3.0 / 4.0) * __qd2 * __qd2
            + __T::from_f64(27.0 / 40.0) * __t2 + __T::from_f64(3.0 / 4.0) * __q2 * __t2;
        __kinetic
    }
    /**The potential energy (zero at y = 0).

```text
V = 38259/4000 s1 + 2943/200 s1 q2
```


Cost: 3 multiplications, 1 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn potential_energy<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> __T {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [(__s1, _)] = ::planar_arm::__private::sin_cos([__q1]);
        let __potential = __T::from_f64(38259.0 / 4000.0) * __s1
            + __T::from_f64(2943.0 / 200.0) * __s1 * __q2;
        __potential
    }
    /**The partial derivatives of `inverse_dynamics`, `(dtau/dq, dtau/dqd)` (`dtau/dqdd` is `mass_matrix`), straight-line code differentiated exactly at compile time. Coulomb friction contributes 0 to `dtau/dqd`, also at `qd_i = 0` where it jumps.

Differentiated exactly at compile time: each torque's expanded formula differentiated symbolically (exact rational coefficients), evaluated term by term.

Cost: 17 multiplications, 10 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn inverse_dynamics_derivatives(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
    ) {
        ::planar_arm::__private::dispatch(::planar_arm::__private::InverseDynamicsDerivatives::<
            Self,
            2,
        > {
            arm: self,
            q: __q,
            qd: __qd,
            qdd: __qdd,
        })
    }
    #[doc(hidden)]
    #[inline(always)]
    fn __inverse_dynamics_derivatives_kernel(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
    ) {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let [__qdd1, _] = ::planar_arm::__private::unpack(__qdd);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __dtau1_dq1 = -((38259.0 / 4000.0) * __s1) - (2943.0 / 200.0) * __s1 * __q2;
        let __dtau2_dq1 = (2943.0 / 200.0) * __c1;
        let __dtau1_dq2 = __dtau2_dq1 + (27.0 / 20.0) * __qdd1 + 3.0 * __qd1 * __qd2
            + 3.0 * __q2 * __qdd1;
        let __dtau2_dq2 = -((3.0 / 2.0) * __qd1 * __qd1);
        let __dtau1_dqd1 = (27.0 / 20.0) * __qd2 + 3.0 * __q2 * __qd2;
        let __t1 = (27.0 / 20.0) * __qd1;
        let __t2 = 3.0 * __q2 * __qd1;
        let __dtau1_dqd2 = __t1 + __t2;
        let __dtau2_dqd1 = -__t1 - __t2;
        let __dtau2_dqd2 = 0.0;
        (
            ::planar_arm::__private::columns([
                [__dtau1_dq1, __dtau2_dq1],
                [__dtau1_dq2, __dtau2_dq2],
            ]),
            ::planar_arm::__private::columns([
                [__dtau1_dqd1, __dtau2_dqd1],
                [__dtau1_dqd2, __dtau2_dqd2],
            ]),
        )
    }
    /**The partial derivatives of `forward_dynamics`, `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, straight-line code built at compile time. Coulomb friction as in `inverse_dynamics_derivatives`.

qdd from the forward dynamics program; dtau/dq and dtau/dqd at that qdd as `inverse_dynamics_derivatives` computes them; M^-1 by Cramer's rule with 1 / det M computed once; then dqdd/dq = -M^-1 dtau/dq and dqdd/dqd = -M^-1 dtau/dqd as products.

Cost: 36 multiplications, 18 additions, 2 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn forward_dynamics_derivatives(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
    ) {
        ::planar_arm::__private::dispatch(::planar_arm::__private::ForwardDynamicsDerivatives::<
            Self,
            2,
        > {
            arm: self,
            q: __q,
            qd: __qd,
            tau: __tau,
        })
    }
    #[doc(hidden)]
    #[inline(always)]
    fn __forward_dynamics_derivatives_kernel(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 2, 2>,
    ) {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2] = ::planar_arm::__private::unpack(__qd);
        let [__tau1, _] = ::planar_arm::__private::unpack(__tau);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __t1 = (3.0 / 2.0) * __q2 * __q2 + (3.0 / 8.0) + (27.0 / 20.0) * __q2;
        let __t2 = __qd1 * __qd2;
        let __t3 = (2943.0 / 200.0) * __c1;
        let __rhs1 = __tau1 - ((27.0 / 20.0) * __t2 + 3.0 * __q2 * __t2)
            - ((38259.0 / 4000.0) * __c1 + __q2 * __t3);
        let __det = (3.0 / 2.0) * __t1;
        let __t4 = (3.0 / 2.0) * __rhs1 / __det;
        let __t5 = (27.0 / 20.0) * __qd1;
        let __t6 = 3.0 * __q2 * __qd1;
        let __inv_det = 1.0 / __det;
        let __dqdd1_dtau1 = (3.0 / 2.0) * __inv_det;
        let __dqdd2_dtau2 = __t1 * __inv_det;
        let __t7 = -__dqdd1_dtau1;
        let __t8 = -__dqdd2_dtau2;
        let __dqdd1_dq1 = (-((38259.0 / 4000.0) * __s1) - __q2 * (2943.0 / 200.0) * __s1)
            * __t7;
        let __dqdd2_dq1 = __t3 * __t8;
        let __dqdd1_dq2 = (__t3 + (27.0 / 20.0) * __t4 + 3.0 * __t2 + 3.0 * __q2 * __t4)
            * __t7;
        let __dqdd2_dq2 = (-((3.0 / 2.0) * __qd1 * __qd1)) * __t8;
        let __dqdd1_dqd1 = ((27.0 / 20.0) * __qd2 + 3.0 * __q2 * __qd2) * __t7;
        let __dqdd2_dqd1 = (-__t5 - __t6) * __t8;
        let __dqdd1_dqd2 = (__t5 + __t6) * __t7;
        let __dqdd2_dqd2 = 0.0;
        (
            ::planar_arm::__private::columns([
                [__dqdd1_dq1, __dqdd2_dq1],
                [__dqdd1_dq2, __dqdd2_dq2],
            ]),
            ::planar_arm::__private::columns([
                [__dqdd1_dqd1, __dqdd2_dqd1],
                [__dqdd1_dqd2, __dqdd2_dqd2],
            ]),
            ::planar_arm::__private::columns([
                [__dqdd1_dtau1, __dqdd2_dqd2],
                [__dqdd2_dqd2, __dqdd2_dtau2],
            ]),
        )
    }
    #[doc(hidden)]
    type __Frozen = ::planar_arm::__private::Block<0>;
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::PlanarArm<2> for Polar {
    const EXACT: ::planar_arm::exact::Derivation<2> = {
        const __NAMES: &[&::core::primitive::str] = &[];
        ::planar_arm::exact::Derivation {
            kinetic_energy: ::planar_arm::__private::terms(
                b"AGgBBACAAGIBDCAA2BwCCACFBAAGICACFCA",
                __NAMES,
            ),
            potential_energy: ::planar_arm::__private::terms(
                b"Cm3qCg6HBBABCAAC+3FwMBBABCBFBA",
                __NAMES,
            ),
            mass_matrix: [
                [
                    ::planar_arm::__private::terms(b"AGQAAA2BoBBFBAAGEBFCA", __NAMES),
                    ::planar_arm::__private::terms(b"", __NAMES),
                ],
                [
                    ::planar_arm::__private::terms(b"", __NAMES),
                    ::planar_arm::__private::terms(b"AGEAA", __NAMES),
                ],
            ],
            coriolis: [
                ::planar_arm::__private::terms(b"A2BoBCABDBAAGCDABDBFBA", __NAMES),
                ::planar_arm::__private::terms(b"A1BwCBACAAFECACFBA", __NAMES),
            ],
            gravity: [
                ::planar_arm::__private::terms(
                    b"Bm3qCg6HBBABCAAB+3FwMBBABCBFBA",
                    __NAMES,
                ),
                ::planar_arm::__private::terms(b"C+3FwMBBABCAA", __NAMES),
            ],
        }
    };
    ///The joints' names, base first: the order of `q`.
    const JOINT_NAMES: [&'static ::core::primitive::str; 2] = ["turret", "boom"];
    #[inline]
    fn model(&self) -> ::planar_arm::Model<2> {
        ::planar_arm::Model {
            links: [
                ::planar_arm::Link {
                    length: (1.0 / 5.0),
                    mass: 3.0,
                    inertia: (1.0 / 100.0),
                    com: ::planar_arm::nalgebra::Vector2::new((1.0 / 10.0), 0.0),
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    joint: ::planar_arm::Joint::Revolute,
                    range: ::core::option::Option::None,
                    offset: 0.0,
                    reversed: false,
                    stiffness: 0.0,
                    springref: 0.0,
                },
                ::planar_arm::Link {
                    length: (1.0 / 2.0),
                    mass: (3.0 / 2.0),
                    inertia: (1.0 / 32.0),
                    com: ::planar_arm::nalgebra::Vector2::new((1.0 / 4.0), 0.0),
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    joint: ::planar_arm::Joint::Prismatic,
                    range: ::core::option::Option::Some((0.0, (3.0 / 5.0))),
                    offset: 0.0,
                    reversed: false,
                    stiffness: 0.0,
                    springref: 0.0,
                },
            ],
            gravity: ::planar_arm::nalgebra::Vector2::new(0.0, (-(981.0 / 100.0))),
            payload: ::planar_arm::Payload::NONE,
        }
    }
    /**The tip pose; the orientation is the last link's angle q1.

```text
x = 7/10 c1 + c1 q2
y = 7/10 s1 + s1 q2
```


Cost: 4 multiplications, 2 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn tip_pose(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
    ) -> ::planar_arm::nalgebra::Isometry2<::core::primitive::f64> {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __x = (7.0 / 10.0) * __c1 + __c1 * __q2;
        let __y = (7.0 / 10.0) * __s1 + __s1 * __q2;
        ::planar_arm::__private::pose(__x, __y, __c1, __s1)
    }
    /**The Jacobian d(x, y, phi)/dq.

```text
J11 = -7/10 s1 - s1 q2
J12 = c1
J21 = 7/10 c1 + c1 q2
J22 = s1
J31 = 1
J32 = 0
```


Cost: 4 multiplications, 3 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn jacobian<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 3, 2> {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __j11 = -(__T::from_f64(7.0 / 10.0) * __s1) - __s1 * __q2;
        let __j21 = __T::from_f64(7.0 / 10.0) * __c1 + __c1 * __q2;
        let __j31 = __T::from_f64(1.0);
        let __j32 = __T::from_f64(0.0);
        ::planar_arm::__private::columns([[__j11, __j21, __j31], [__c1, __s1, __j32]])
    }
    /**The position of each joint, joint 1 at the origin.

Cost: 4 multiplications, 2 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn joint_positions<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 2>,
    ) -> [::planar_arm::nalgebra::Point2<__T>; 2] {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __x2 = __T::from_f64(1.0 / 5.0) * __c1 + __c1 * __q2;
        let __y2 = __T::from_f64(1.0 / 5.0) * __s1 + __s1 * __q2;
        let __x1 = __T::from_f64(0.0);
        [
            ::planar_arm::nalgebra::Point2::new(__x1, __x1),
            ::planar_arm::nalgebra::Point2::new(__x2, __y2),
        ]
    }
    /**The tip in polar form: r from r^2 (which does not depend on q1), theta = atan2(y, x).

```text
r^2 = 49/100 + 7/5 q2 + q2^2
```


Cost: 6 multiplications, 4 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn tip_polar(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
    ) -> (::core::primitive::f64, ::core::primitive::f64) {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __r2 = __q2 * __q2 + (49.0 / 100.0) + (7.0 / 5.0) * __q2;
        let __x = (7.0 / 10.0) * __c1 + __q2 * __c1;
        let __y = (7.0 / 10.0) * __s1 + __q2 * __s1;
        ::planar_arm::__private::polar(__r2, __x, __y)
    }
    /**Statics: tau = J^T (u, v, torque), the motor torques that make the tip exert force (u, v) and torque `torque`.

Cost: 8 multiplications, 7 additions, 0 divisions, 1 sin_cos pairs.*/
    #[inline]
    fn joint_torques(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __force: &::planar_arm::nalgebra::Vector2<::core::primitive::f64>,
        __torque: ::core::primitive::f64,
    ) -> ::planar_arm::nalgebra::SVector<::core::primitive::f64, 2> {
        let [__q1, __q2] = ::planar_arm::__private::unpack(__q);
        let [__u, __v] = ::planar_arm::__private::unpack(__force);
        let [(__s1, __c1)] = ::planar_arm::__private::sin_cos([__q1]);
        let __tau1 = __torque + __u * (-((7.0 / 10.0) * __s1) - __s1 * __q2)
            + __v * ((7.0 / 10.0) * __c1 + __c1 * __q2);
        let __tau2 = __torque + __u * __c1 + __v * __s1;
        ::planar_arm::__private::vector([__tau1, __tau2])
    }
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::kinematics::ClosedFormIk<2> for Polar {
    type Target = ::planar_arm::nalgebra::Point2<::core::primitive::f64>;
    ///The polar arm: q1 = atan2(y, x) and the slide r - l1 - l2, or the opposite direction with the slide -r - l1 - l2; the branches within the ranges (see `kinematics::ik_rp`).
    #[inline]
    fn inverse_kinematics(
        &self,
        __target: &::planar_arm::nalgebra::Point2<::core::primitive::f64>,
    ) -> ::core::result::Result<
        [::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>; 2],
        ::planar_arm::ArmError,
    > {
        ::planar_arm::kinematics::ik_rp(
            (1.0 / 5.0),
            (1.0 / 2.0),
            ::core::option::Option::None,
            ::core::option::Option::Some((0.0, (3.0 / 5.0))),
            __target,
        )
    }
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::kinematics::TipForce for Polar {
    /// By the generated Jacobian: `J^T F = tau`, a prismatic joint's entry of
    /// `tau` a force along it.
    #[inline]
    fn tip_force(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 2>,
    ) -> ::core::result::Result<
        ::planar_arm::nalgebra::Vector2<::core::primitive::f64>,
        ::planar_arm::ArmError,
    > {
        ::planar_arm::__private::tip_force_by_jacobian(
                &::planar_arm::PlanarArm::jacobian(self, __q),
                __q,
                __tau,
            )
            .map(|w| ::planar_arm::nalgebra::Vector2::new(w[0], w[1]))
    }
}
