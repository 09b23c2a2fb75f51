#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::Dynamics<3> for Paper3 {
    /**The mass matrix M(q), derived exactly (symmetric; upper triangle shown). Joint angles `q`, rates `qd`, accelerations `qdd` (1-based in the formulas); `cK` and `sK...` are the cosine and sine of the sum of the joint angles named by the digits.

```text
M11 = 4 + 3 c2 + c23 + c3
M12 = 5/3 + 3/2 c2 + 1/2 c23 + c3
M13 = 1/3 + 1/2 c23 + 1/2 c3
M22 = 5/3 + c3
M23 = 1/3 + 1/2 c3
M33 = 1/3
```


Cost: 6 multiplications, 11 additions, 0 divisions, 2 sin_cos pairs.*/
    #[inline]
    fn mass_matrix<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 3, 3> {
        let _ = (&self.upper, &self.fore, &self.hand);
        let [_, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [(__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
        ]);
        let __c23 = __c2 * __c3 - __s2 * __s3;
        let __m11 = __T::from_f64(4.0) + __T::from_f64(3.0) * __c2 + __c3 + __c23;
        let __t1 = __T::from_f64(1.0 / 2.0) * __c23;
        let __m12 = __T::from_f64(5.0 / 3.0) + __T::from_f64(3.0 / 2.0) * __c2 + __c3
            + __t1;
        let __t2 = __T::from_f64(1.0 / 2.0) * __c3;
        let __m13 = __t2 + __t1 + __T::from_f64(1.0 / 3.0);
        let __m22 = __c3 + __T::from_f64(5.0 / 3.0);
        let __m23 = __T::from_f64(1.0 / 3.0) + __t2;
        let __m33 = __T::from_f64(1.0 / 3.0);
        ::planar_arm::__private::columns([
            [__m11, __m12, __m13],
            [__m12, __m22, __m23],
            [__m13, __m23, __m33],
        ])
    }
    /**The velocity-product torques c(q, qd).

```text
c1 = (-3 s2 - s23) qd1 qd2 + (-s23 - s3) qd1 qd3 + (-3/2 s2 - 1/2 s23) qd2^2 + (-s23 - s3) qd2 qd3 + (-1/2 s23 - 1/2 s3) qd3^2
c2 = (3/2 s2 + 1/2 s23) qd1^2 - s3 qd1 qd3 - s3 qd2 qd3 - 1/2 s3 qd3^2
c3 = (1/2 s23 + 1/2 s3) qd1^2 + s3 qd1 qd2 + 1/2 s3 qd2^2
```


Evaluated not term by term but by the planar recursive Newton-Euler algorithm unrolled for this arm (the same function, fewer operations): link-frame velocities and accelerations outwards, forces and moments inwards, one rotation by each joint's (cos, sin) per pass, the link constants folded in.

Cost: 19 multiplications, 17 additions, 0 divisions, 2 sin_cos pairs.*/
    #[inline]
    fn coriolis<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 3> {
        let [_, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [(__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
        ]);
        let __ex1 = -(__qd1 * __qd1);
        let __ax2 = __ex1 * __c2;
        let __t1 = __ex1 * __s2;
        let __ay2 = -__t1;
        let __w2 = __qd1 + __qd2;
        let __t2 = __w2 * __w2;
        let __ex2 = __ax2 - __t2;
        let __ax3 = __ex2 * __c3 + __ay2 * __s3;
        let __ay3 = __ay2 * __c3 - __ex2 * __s3;
        let __w3 = __w2 + __qd3;
        let __fx3 = __ax3 - __T::from_f64(1.0 / 2.0) * __w3 * __w3;
        let __cor3 = __T::from_f64(1.0 / 2.0) * __ay3;
        let __t3 = __s3 * __fx3 + __c3 * __ay3;
        let __fx2 = __ax2 - __T::from_f64(1.0 / 2.0) * __t2 + __c3 * __fx3
            - __s3 * __ay3;
        let __fy2 = __t3 - __t1;
        let __cor2 = __cor3 + __T::from_f64(1.0 / 2.0) * __ay2 + __t3;
        let __fy1 = __s2 * __fx2 + __c2 * __fy2;
        let __cor1 = __cor2 + __fy1;
        ::planar_arm::__private::vector([__cor1, __cor2, __cor3])
    }
    /**The Coriolis matrix from Christoffel symbols, C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k.

```text
C11 = (-3/2 s2 - 1/2 s23) qd2 + (-1/2 s23 - 1/2 s3) qd3
C12 = (-3/2 s2 - 1/2 s23) qd1 + (-3/2 s2 - 1/2 s23) qd2 + (-1/2 s23 - 1/2 s3) qd3
C13 = (-1/2 s23 - 1/2 s3) qd1 + (-1/2 s23 - 1/2 s3) qd2 + (-1/2 s23 - 1/2 s3) qd3
C21 = (3/2 s2 + 1/2 s23) qd1 - 1/2 s3 qd3
C22 = -1/2 s3 qd3
C23 = -1/2 s3 qd1 - 1/2 s3 qd2 - 1/2 s3 qd3
C31 = (1/2 s23 + 1/2 s3) qd1 + 1/2 s3 qd2
C32 = 1/2 s3 qd1 + 1/2 s3 qd2
C33 = 0
```


Evaluated in the links' absolute angles, where each entry of C is a sum of products `dM~_ab/dphi_b w_b` of one small derivative and one absolute rate (see `planar_arm::symbolic::christoffel`).

Cost: 11 multiplications, 13 additions, 0 divisions, 2 sin_cos pairs.*/
    #[inline]
    fn coriolis_matrix<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 3, 3> {
        let [_, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [(__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
        ]);
        let __t1 = __qd1 + __qd2;
        let __t2 = __t1 + __qd3;
        let __t3 = __T::from_f64(3.0 / 2.0) * __s2;
        let __s23 = __s2 * __c3 + __c2 * __s3;
        let __t4 = __T::from_f64(1.0 / 2.0) * __s23;
        let __t5 = __T::from_f64(1.0 / 2.0) * __s3;
        let __t6 = -(__t2 * __t4);
        let __t7 = __t6 - __t1 * __t3;
        let __t8 = __t2 * __t5;
        let __cm23 = -__t8;
        let __cm32 = __t1 * __t5;
        let __cm31 = __cm32 + __qd1 * __t4;
        let __cm21 = __qd1 * __t3 - __t8 + __cm31;
        let __cm11 = __t7 + __cm21;
        let __cm22 = __cm32 - __t8;
        let __cm12 = __t7 + __cm22;
        let __cm13 = __t6 - __t8;
        let __cm33 = __T::from_f64(0.0);
        ::planar_arm::__private::columns([
            [__cm11, __cm21, __cm31],
            [__cm12, __cm22, __cm32],
            [__cm13, __cm23, __cm33],
        ])
    }
    /**The gravity torques g(q) = dV/dq.

```text
g1 = 981/40 c1 + 2943/200 c12 + 981/200 c123
g2 = 2943/200 c12 + 981/200 c123
g3 = 981/200 c123
```


Cost: 9 multiplications, 6 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn gravity<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 3> {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __c12 = __c1 * __c2 - __s1 * __s2;
        let __s12 = __s1 * __c2 + __c1 * __s2;
        let __t1 = __T::from_f64(2943.0 / 200.0) * __c12;
        let __c123 = __c12 * __c3 - __s12 * __s3;
        let __g3 = __T::from_f64(981.0 / 200.0) * __c123;
        let __g1 = __g3 + __T::from_f64(981.0 / 40.0) * __c1 + __t1;
        let __g2 = __t1 + __g3;
        ::planar_arm::__private::vector([__g1, __g2, __g3])
    }
    /**The joint friction torques f(qd): viscous `damping qd_i` plus Coulomb `frictionloss sign(qd_i)`, with sign(0) = 0 (MuJoCo's `damping` and `frictionloss`). The Coulomb term jumps at `qd_i = 0`.

```text
f1 = 0
f2 = 0
f3 = 0
```


Cost: 0 multiplications, 0 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn friction<__T: ::planar_arm::Real>(
        &self,
        _: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 3> {
        let __f1 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__f1, __f1, __f1])
    }
    /**The bias h(q, qd) = c + g + f: every torque but the inertial one, so that `inverse_dynamics(q, qd, qdd) = mass_matrix(q) qdd + bias(q, qd)` (Pinocchio's `nonLinearEffects`, MuJoCo's `qfrc_bias` plus its passive joint friction).

Evaluated not term by term but by the planar recursive Newton-Euler algorithm unrolled for this arm (the same function, fewer operations): link-frame velocities and accelerations outwards, forces and moments inwards, one rotation by each joint's (cos, sin) per pass, the link constants folded in.

Cost: 24 multiplications, 19 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn bias<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 3> {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __ax1 = __T::from_f64(981.0 / 100.0) * __s1;
        let __ay1 = __T::from_f64(981.0 / 100.0) * __c1;
        let __ex1 = __ax1 - __qd1 * __qd1;
        let __ax2 = __ex1 * __c2 + __ay1 * __s2;
        let __ay2 = __ay1 * __c2 - __ex1 * __s2;
        let __w2 = __qd1 + __qd2;
        let __t1 = __w2 * __w2;
        let __ex2 = __ax2 - __t1;
        let __ax3 = __ex2 * __c3 + __ay2 * __s3;
        let __ay3 = __ay2 * __c3 - __ex2 * __s3;
        let __w3 = __w2 + __qd3;
        let __fx3 = __ax3 - __T::from_f64(1.0 / 2.0) * __w3 * __w3;
        let __h3 = __T::from_f64(1.0 / 2.0) * __ay3;
        let __t2 = __s3 * __fx3 + __c3 * __ay3;
        let __fx2 = __ax2 - __T::from_f64(1.0 / 2.0) * __t1 + __c3 * __fx3
            - __s3 * __ay3;
        let __fy2 = __ay2 + __t2;
        let __h2 = __h3 + __T::from_f64(1.0 / 2.0) * __ay2 + __t2;
        let __h1 = __h2 + __T::from_f64(1.0 / 2.0) * __ay1 + __s2 * __fx2 + __c2 * __fy2;
        ::planar_arm::__private::vector([__h1, __h2, __h3])
    }
    /**M(q) and h(q, qd) = c + g + f in one pass, sharing the trigonometry and every common subexpression: what computed-torque and operational-space controllers need every cycle.

M by the composite-rigid-body algorithm unrolled for this arm, h by the recursive Newton-Euler algorithm unrolled for this arm.

Cost: 31 multiplications, 28 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn mass_matrix_and_bias<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<__T, 3, 3>,
        ::planar_arm::nalgebra::SVector<__T, 3>,
    ) {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __t1 = __T::from_f64(1.0 / 2.0) * __c3;
        let __hy2 = __T::from_f64(1.0 / 2.0) * __s3;
        let __m23 = __T::from_f64(1.0 / 3.0) + __t1;
        let __t2 = __s2 * __hy2;
        let __m13 = __m23 + __c2 * __t1 - __t2;
        let __hx2 = __t1 + __T::from_f64(3.0 / 2.0);
        let __m22 = __T::from_f64(2.0) * __t1 + __T::from_f64(5.0 / 3.0);
        let __t3 = __c2 * __hx2 - __t2;
        let __m12 = __m22 + __t3;
        let __m11 = __T::from_f64(2.0) * __t3 + __m22 + __T::from_f64(7.0 / 3.0);
        let __ax1 = __T::from_f64(981.0 / 100.0) * __s1;
        let __ay1 = __T::from_f64(981.0 / 100.0) * __c1;
        let __ex1 = __ax1 - __qd1 * __qd1;
        let __ax2 = __c2 * __ex1 + __s2 * __ay1;
        let __ay2 = __c2 * __ay1 - __s2 * __ex1;
        let __w2 = __qd1 + __qd2;
        let __t4 = __w2 * __w2;
        let __ex2 = __ax2 - __t4;
        let __ax3 = __c3 * __ex2 + __s3 * __ay2;
        let __ay3 = __c3 * __ay2 - __s3 * __ex2;
        let __w3 = __w2 + __qd3;
        let __fx3 = __ax3 - __T::from_f64(1.0 / 2.0) * __w3 * __w3;
        let __h3 = __T::from_f64(1.0 / 2.0) * __ay3;
        let __t5 = __s3 * __fx3 + __c3 * __ay3;
        let __fx2 = __ax2 - __T::from_f64(1.0 / 2.0) * __t4 + __c3 * __fx3
            - __s3 * __ay3;
        let __fy2 = __ay2 + __t5;
        let __h2 = __h3 + __T::from_f64(1.0 / 2.0) * __ay2 + __t5;
        let __h1 = __h2 + __T::from_f64(1.0 / 2.0) * __ay1 + __s2 * __fx2 + __c2 * __fy2;
        let __m33 = __T::from_f64(1.0 / 3.0);
        (
            ::planar_arm::__private::columns([
                [__m11, __m12, __m13],
                [__m12, __m22, __m23],
                [__m13, __m23, __m33],
            ]),
            ::planar_arm::__private::vector([__h1, __h2, __h3]),
        )
    }
    /**Lagrange's equation, tau_i = d/dt dL/dqd_i - dL/dq_i, expanded, plus the joint friction f(qd) (see `friction`).

```text
tau1 = (981/40 c1 + 2943/200 c12 + 981/200 c123) + (4 + 3 c2 + c23 + c3) qdd1 + (5/3 + 3/2 c2 + 1/2 c23 + c3) qdd2 + (1/3 + 1/2 c23 + 1/2 c3) qdd3 + (-3 s2 - s23) qd1 qd2 + (-s23 - s3) qd1 qd3 + (-3/2 s2 - 1/2 s23) qd2^2 + (-s23 - s3) qd2 qd3 + (-1/2 s23 - 1/2 s3) qd3^2
tau2 = (2943/200 c12 + 981/200 c123) + (5/3 + 3/2 c2 + 1/2 c23 + c3) qdd1 + (5/3 + c3) qdd2 + (1/3 + 1/2 c3) qdd3 + (3/2 s2 + 1/2 s23) qd1^2 - s3 qd1 qd3 - s3 qd2 qd3 - 1/2 s3 qd3^2
tau3 = 981/200 c123 + (1/3 + 1/2 c23 + 1/2 c3) qdd1 + (1/3 + 1/2 c3) qdd2 + 1/3 qdd3 + (1/2 s23 + 1/2 s3) qd1^2 + s3 qd1 qd2 + 1/2 s3 qd2^2
```


Evaluated not term by term but by the planar recursive Newton-Euler algorithm unrolled for this arm (the same function, fewer operations): link-frame velocities and accelerations outwards, forces and moments inwards, one rotation by each joint's (cos, sin) per pass, the link constants folded in.

Cost: 29 multiplications, 28 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn inverse_dynamics<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qdd: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 3> {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [__qdd1, __qdd2, __qdd3] = ::planar_arm::__private::unpack(__qdd);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __ax1 = __T::from_f64(981.0 / 100.0) * __s1;
        let __ay1 = __T::from_f64(981.0 / 100.0) * __c1;
        let __ex1 = __ax1 - __qd1 * __qd1;
        let __ey1 = __qdd1 + __ay1;
        let __ax2 = __ex1 * __c2 + __ey1 * __s2;
        let __ay2 = __ey1 * __c2 - __ex1 * __s2;
        let __w2 = __qd1 + __qd2;
        let __al2 = __qdd1 + __qdd2;
        let __t1 = __w2 * __w2;
        let __ex2 = __ax2 - __t1;
        let __ey2 = __ay2 + __al2;
        let __ax3 = __ex2 * __c3 + __ey2 * __s3;
        let __ay3 = __ey2 * __c3 - __ex2 * __s3;
        let __w3 = __w2 + __qd3;
        let __al3 = __qdd3 + __al2;
        let __fx3 = __ax3 - __T::from_f64(1.0 / 2.0) * __w3 * __w3;
        let __fy3 = __ay3 + __T::from_f64(1.0 / 2.0) * __al3;
        let __tau3 = __T::from_f64(1.0 / 3.0) * __al3 + __T::from_f64(1.0 / 2.0) * __ay3;
        let __t2 = __s3 * __fx3 + __c3 * __fy3;
        let __fx2 = __ax2 - __T::from_f64(1.0 / 2.0) * __t1 + __c3 * __fx3
            - __s3 * __fy3;
        let __fy2 = __ay2 + __T::from_f64(1.0 / 2.0) * __al2 + __t2;
        let __tau2 = __tau3 + __T::from_f64(1.0 / 3.0) * __al2
            + __T::from_f64(1.0 / 2.0) * __ay2 + __t2;
        let __tau1 = __tau2 + __T::from_f64(1.0 / 3.0) * __qdd1
            + __T::from_f64(1.0 / 2.0) * __ay1 + __s2 * __fx2 + __c2 * __fy2;
        ::planar_arm::__private::vector([__tau1, __tau2, __tau3])
    }
    /**The kinetic energy.

```text
T = (2 + 3/2 c2 + 1/2 c23 + 1/2 c3) qd1^2 + (5/3 + 3/2 c2 + 1/2 c23 + c3) qd1 qd2 + (1/3 + 1/2 c23 + 1/2 c3) qd1 qd3 + (5/6 + 1/2 c3) qd2^2 + (1/3 + 1/2 c3) qd2 qd3 + 1/6 qd3^2
```


Cost: 17 multiplications, 16 additions, 0 divisions, 2 sin_cos pairs.*/
    #[inline]
    fn kinetic_energy<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> __T {
        let [_, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [(__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
        ]);
        let __t1 = __T::from_f64(3.0 / 2.0) * __c2;
        let __c23 = __c2 * __c3 - __s2 * __s3;
        let __t2 = __T::from_f64(1.0 / 2.0) * __c23;
        let __t3 = __T::from_f64(1.0 / 2.0) * __c3;
        let __kinetic = (__t3 + __t2 + __T::from_f64(1.0 / 3.0)) * __qd1 * __qd3
            + (__T::from_f64(2.0) + __t1 + __t2 + __t3) * __qd1 * __qd1
            + (__t1 + __T::from_f64(5.0 / 3.0) + __c3 + __t2) * __qd1 * __qd2
            + __T::from_f64(1.0 / 6.0) * __qd3 * __qd3
            + (__t3 + __T::from_f64(5.0 / 6.0)) * __qd2 * __qd2
            + (__t3 + __T::from_f64(1.0 / 3.0)) * __qd2 * __qd3;
        __kinetic
    }
    /**The potential energy (zero at y = 0).

```text
V = 981/40 s1 + 2943/200 s12 + 981/200 s123
```


Cost: 9 multiplications, 5 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn potential_energy<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> __T {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __c12 = __c1 * __c2 - __s1 * __s2;
        let __s12 = __s1 * __c2 + __c1 * __s2;
        let __s123 = __s12 * __c3 + __c12 * __s3;
        let __potential = __T::from_f64(981.0 / 200.0) * __s123
            + __T::from_f64(981.0 / 40.0) * __s1 + __T::from_f64(2943.0 / 200.0) * __s12;
        __potential
    }
    /**The partial derivatives of `inverse_dynamics`, `(dtau/dq, dtau/dqd)` (`dtau/dqdd` is `mass_matrix`), straight-line code differentiated exactly at compile time. Coulomb friction contributes 0 to `dtau/dqd`, also at `qd_i = 0` where it jumps.

Differentiated exactly at compile time: each torque's expanded formula differentiated symbolically (exact rational coefficients), evaluated term by term.

Cost: 68 multiplications, 76 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn inverse_dynamics_derivatives(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
    ) {
        ::planar_arm::__private::dispatch(::planar_arm::__private::InverseDynamicsDerivatives::<
            Self,
            3,
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
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
    ) {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [__qdd1, __qdd2, __qdd3] = ::planar_arm::__private::unpack(__qdd);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __c12 = __c1 * __c2 - __s1 * __s2;
        let __s12 = __s1 * __c2 + __c1 * __s2;
        let __t1 = (2943.0 / 200.0) * __s12;
        let __s123 = __s12 * __c3 + __c12 * __s3;
        let __t2 = (981.0 / 200.0) * __s123;
        let __dtau1_dq1 = -((981.0 / 40.0) * __s1) - (__t1 + __t2);
        let __dtau2_dq1 = -__t1 - __t2;
        let __t3 = 3.0 * __s2;
        let __c23 = __c2 * __c3 - __s2 * __s3;
        let __s23 = __s2 * __c3 + __c2 * __s3;
        let __t4 = -__t3 - __s23;
        let __t5 = (1.0 / 2.0) * __s23;
        let __t6 = -((3.0 / 2.0) * __s2) - __t5;
        let __t7 = __qd1 * __qd2;
        let __t8 = __qd1 * __qd3;
        let __t9 = (3.0 / 2.0) * __c2;
        let __t10 = (1.0 / 2.0) * __c23;
        let __t11 = __qd2 * __qd2;
        let __t12 = __qd2 * __qd3;
        let __t13 = __qd3 * __qd3;
        let __dtau1_dq2 = __t6 * __qdd2 + __dtau2_dq1 + __t4 * __qdd1
            + (-(3.0 * __c2) - __c23) * __t7 + (-__t9 - __t10) * __t11
            - (__t5 * __qdd3 + __c23 * __t8 + __c23 * __t12 + __t10 * __t13);
        let __t14 = -__s23 - __s3;
        let __t15 = -__t5;
        let __t16 = __t15 - __s3;
        let __t17 = (1.0 / 2.0) * __s3;
        let __t18 = __t15 - __t17;
        let __t19 = -__c23 - __c3;
        let __t20 = (1.0 / 2.0) * __c3;
        let __dtau1_dq3 = __qdd3 * __t18 + __qdd1 * __t14 + __qdd2 * __t16
            + __t13 * (-__t10 - __t20) + __t8 * __t19 + __t12 * __t19
            - (__t10 * __t11 + __t2 + __c23 * __t7);
        let __t21 = __qd1 * __qd1;
        let __dtau2_dq2 = (__t9 + __t10) * __t21 + __dtau2_dq1 + __qdd1 * __t6;
        let __t22 = __t10 * __t21;
        let __dtau2_dq3 = __qdd1 * __t16 + __t22
            - (__qdd3 * __t17 + __t2 + __s3 * __qdd2 + __t13 * __t20 + __c3 * __t8
                + __c3 * __t12);
        let __dtau3_dq1 = -__t2;
        let __dtau3_dq2 = __t22 - (__t2 + __qdd1 * __t5);
        let __dtau3_dq3 = __qdd1 * __t18 + (__t10 + __t20) * __t21 + __c3 * __t7
            + __t11 * __t20 - (__t2 + __qdd2 * __t17);
        let __t23 = __t4 * __qd2;
        let __t24 = __qd3 * __t14;
        let __dtau1_dqd1 = __t23 + __t24;
        let __dtau1_dqd2 = __t24 + __t23 + __t4 * __qd1;
        let __dtau1_dqd3 = __t24 + __qd1 * __t14 + __qd2 * __t14;
        let __t25 = __s3 * __qd3;
        let __dtau2_dqd1 = (__t3 + __s23) * __qd1 - __t25;
        let __dtau2_dqd2 = -__t25;
        let __t26 = __s3 * __qd1;
        let __t27 = __s3 * __qd2;
        let __dtau3_dqd2 = __t26 + __t27;
        let __dtau2_dqd3 = -__t26 - (__t25 + __t27);
        let __dtau3_dqd1 = __t27 + __qd1 * (__s3 + __s23);
        let __dtau3_dqd3 = 0.0;
        (
            ::planar_arm::__private::columns([
                [__dtau1_dq1, __dtau2_dq1, __dtau3_dq1],
                [__dtau1_dq2, __dtau2_dq2, __dtau3_dq2],
                [__dtau1_dq3, __dtau2_dq3, __dtau3_dq3],
            ]),
            ::planar_arm::__private::columns([
                [__dtau1_dqd1, __dtau2_dqd1, __dtau3_dqd1],
                [__dtau1_dqd2, __dtau2_dqd2, __dtau3_dqd2],
                [__dtau1_dqd3, __dtau2_dqd3, __dtau3_dqd3],
            ]),
        )
    }
    /**The partial derivatives of `forward_dynamics`, `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, straight-line code built at compile time. Coulomb friction as in `inverse_dynamics_derivatives`.

qdd from the forward dynamics program; dtau/dq and dtau/dqd at that qdd as `inverse_dynamics_derivatives` computes them; M^-1 by an unrolled L D L^T factorisation of M, computed once; then dqdd/dq = -M^-1 dtau/dq and dqdd/dqd = -M^-1 dtau/dqd as products.

Cost: 171 multiplications, 178 additions, 3 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn forward_dynamics_derivatives(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
    ) {
        ::planar_arm::__private::dispatch(::planar_arm::__private::ForwardDynamicsDerivatives::<
            Self,
            3,
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
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 3, 3>,
    ) {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3] = ::planar_arm::__private::unpack(__qd);
        let [__tau1, __tau2, __tau3] = ::planar_arm::__private::unpack(__tau);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __t1 = 3.0 * __c2;
        let __c23 = __c2 * __c3 - __s2 * __s3;
        let __s23 = __s2 * __c3 + __c2 * __s3;
        let __t2 = (3.0 / 2.0) * __c2;
        let __t3 = (1.0 / 2.0) * __c23;
        let __t4 = (5.0 / 3.0) + __t2 + __c3 + __t3;
        let __t5 = (1.0 / 2.0) * __c3;
        let __t6 = __t5 + __t3 + (1.0 / 3.0);
        let __t7 = __qd1 * __qd1;
        let __ex1 = -__t7;
        let __ax2 = __c2 * __ex1;
        let __t8 = __s2 * __ex1;
        let __ay2 = -__t8;
        let __w2 = __qd1 + __qd2;
        let __t9 = __w2 * __w2;
        let __ex2 = __ax2 - __t9;
        let __ax3 = __c3 * __ex2 + __s3 * __ay2;
        let __ay3 = __c3 * __ay2 - __s3 * __ex2;
        let __w3 = __w2 + __qd3;
        let __fx3 = __ax3 - (1.0 / 2.0) * __w3 * __w3;
        let __t10 = (1.0 / 2.0) * __ay3;
        let __t11 = __s3 * __fx3 + __c3 * __ay3;
        let __fx2 = __ax2 - (1.0 / 2.0) * __t9 + __c3 * __fx3 - __s3 * __ay3;
        let __fy2 = __t11 - __t8;
        let __t12 = __t10 + (1.0 / 2.0) * __ay2 + __t11;
        let __fy1 = __s2 * __fx2 + __c2 * __fy2;
        let __c12 = __c2 * __c1 - __s2 * __s1;
        let __s12 = __c2 * __s1 + __s2 * __c1;
        let __t13 = (2943.0 / 200.0) * __c12;
        let __c123 = __c3 * __c12 - __s3 * __s12;
        let __s123 = __c3 * __s12 + __s3 * __c12;
        let __t14 = (981.0 / 200.0) * __c123;
        let __rhs1 = __tau1 - (__t12 + __fy1) - (__t14 + (981.0 / 40.0) * __c1 + __t13);
        let __rhs2 = __tau2 - __t12 - (__t13 + __t14);
        let __rhs3 = __tau3 - __t10 - __t14;
        let __d1 = (4.0 + __t1 + __c3 + __c23).max((9.0 / 4503599627370496.0));
        let __inv_d1 = 1.0 / __d1;
        let __l21 = __t4 * __inv_d1;
        let __d2 = (__c3 + (5.0 / 3.0) - __t4 * __l21).max((1.0 / 1688849860263936.0));
        let __inv_d2 = 1.0 / __d2;
        let __l31 = __t6 * __inv_d1;
        let __t15 = (1.0 / 3.0) + __t5 - __t4 * __l31;
        let __l32 = __inv_d2 * __t15;
        let __d3 = ((1.0 / 3.0) - __t6 * __l31 - __t15 * __l32)
            .max(0.00000000000000007401486830834377);
        let __dqdd3_dtau3 = 1.0 / __d3;
        let __t16 = __rhs2 - __rhs1 * __l21;
        let __t17 = __dqdd3_dtau3 * (__rhs3 - __rhs1 * __l31 - __l32 * __t16);
        let __t18 = __inv_d2 * __t16 - __l32 * __t17;
        let __t19 = __rhs1 * __inv_d1 - __l21 * __t18 - __l31 * __t17;
        let __t20 = (2943.0 / 200.0) * __s12;
        let __t21 = (981.0 / 200.0) * __s123;
        let __t22 = -((981.0 / 40.0) * __s1) - (__t20 + __t21);
        let __t23 = -__t20 - __t21;
        let __t24 = 3.0 * __s2;
        let __t25 = -__t24 - __s23;
        let __t26 = (1.0 / 2.0) * __s23;
        let __t27 = -((3.0 / 2.0) * __s2) - __t26;
        let __t28 = __qd1 * __qd2;
        let __t29 = __qd1 * __qd3;
        let __t30 = __qd2 * __qd2;
        let __t31 = __qd2 * __qd3;
        let __t32 = __qd3 * __qd3;
        let __t33 = __t18 * __t27 + __t23 + __t19 * __t25 + (-__t1 - __c23) * __t28
            + (-__t2 - __t3) * __t30
            - (__t17 * __t26 + __c23 * __t29 + __c23 * __t31 + __t3 * __t32);
        let __t34 = -__s23 - __s3;
        let __t35 = -__t26;
        let __t36 = __t35 - __s3;
        let __t37 = (1.0 / 2.0) * __s3;
        let __t38 = __t35 - __t37;
        let __t39 = -__c23 - __c3;
        let __t40 = __t17 * __t38 + __t19 * __t34 + __t18 * __t36
            + __t32 * (-__t3 - __t5) + __t29 * __t39 + __t31 * __t39
            - (__t3 * __t30 + __t21 + __c23 * __t28);
        let __t41 = __t7 * (__t2 + __t3) + __t23 + __t19 * __t27;
        let __t42 = __t3 * __t7;
        let __t43 = __t19 * __t36 + __t42
            - (__t17 * __t37 + __t21 + __s3 * __t18 + __t5 * __t32 + __c3 * __t29
                + __c3 * __t31);
        let __t44 = -__t21;
        let __t45 = __t42 - (__t21 + __t19 * __t26);
        let __t46 = __t19 * __t38 + __t7 * (__t3 + __t5) + __c3 * __t28 + __t5 * __t30
            - (__t21 + __t18 * __t37);
        let __t47 = __qd2 * __t25;
        let __t48 = __qd3 * __t34;
        let __t49 = __t47 + __t48;
        let __t50 = __t48 + __t47 + __qd1 * __t25;
        let __t51 = __t48 + __qd1 * __t34 + __qd2 * __t34;
        let __t52 = __s3 * __qd3;
        let __t53 = __qd1 * (__s23 + __t24) - __t52;
        let __t54 = -__t52;
        let __t55 = __s3 * __qd1;
        let __t56 = __s3 * __qd2;
        let __t57 = __t55 + __t56;
        let __t58 = -__t55 - (__t52 + __t56);
        let __t59 = __t56 + __qd1 * (__s3 + __s23);
        let __t60 = -__l21;
        let __dqdd3_dtau1 = __dqdd3_dtau3 * (-__l31 - __l32 * __t60);
        let __dqdd2_dtau1 = __inv_d2 * __t60 - __l32 * __dqdd3_dtau1;
        let __dqdd1_dtau1 = __inv_d1 - __l21 * __dqdd2_dtau1 - __l31 * __dqdd3_dtau1;
        let __dqdd3_dtau2 = __dqdd3_dtau3 * (-__l32);
        let __dqdd2_dtau2 = __inv_d2 - __l32 * __dqdd3_dtau2;
        let __dqdd1_dtau2 = -(__l21 * __dqdd2_dtau2) - __l31 * __dqdd3_dtau2;
        let __dqdd2_dtau3 = -(__l32 * __dqdd3_dtau3);
        let __dqdd1_dtau3 = -(__l21 * __dqdd2_dtau3) - __l31 * __dqdd3_dtau3;
        let __t61 = -__dqdd1_dtau1;
        let __t62 = -__dqdd2_dtau1;
        let __t63 = -__dqdd3_dtau1;
        let __t64 = -__dqdd2_dtau2;
        let __t65 = -__dqdd3_dtau2;
        let __t66 = -__dqdd3_dtau3;
        let __dqdd1_dq1 = __t44 * __t63 + __t22 * __t61 + __t23 * __t62;
        let __dqdd2_dq1 = __t44 * __t65 + __t22 * __t62 + __t23 * __t64;
        let __dqdd3_dq1 = __t44 * __t66 + __t22 * __t63 + __t23 * __t65;
        let __dqdd1_dq2 = __t45 * __t63 + __t33 * __t61 + __t41 * __t62;
        let __dqdd2_dq2 = __t45 * __t65 + __t33 * __t62 + __t41 * __t64;
        let __dqdd3_dq2 = __t45 * __t66 + __t33 * __t63 + __t41 * __t65;
        let __dqdd1_dq3 = __t46 * __t63 + __t40 * __t61 + __t43 * __t62;
        let __dqdd2_dq3 = __t46 * __t65 + __t40 * __t62 + __t43 * __t64;
        let __dqdd3_dq3 = __t46 * __t66 + __t40 * __t63 + __t43 * __t65;
        let __dqdd1_dqd1 = __t59 * __t63 + __t49 * __t61 + __t53 * __t62;
        let __dqdd2_dqd1 = __t59 * __t65 + __t49 * __t62 + __t53 * __t64;
        let __dqdd3_dqd1 = __t59 * __t66 + __t49 * __t63 + __t53 * __t65;
        let __dqdd1_dqd2 = __t57 * __t63 + __t50 * __t61 + __t54 * __t62;
        let __dqdd2_dqd2 = __t57 * __t65 + __t50 * __t62 + __t54 * __t64;
        let __dqdd3_dqd2 = __t57 * __t66 + __t50 * __t63 + __t54 * __t65;
        let __dqdd1_dqd3 = __t51 * __t61 + __t58 * __t62;
        let __dqdd2_dqd3 = __t51 * __t62 + __t58 * __t64;
        let __dqdd3_dqd3 = __t51 * __t63 + __t58 * __t65;
        (
            ::planar_arm::__private::columns([
                [__dqdd1_dq1, __dqdd2_dq1, __dqdd3_dq1],
                [__dqdd1_dq2, __dqdd2_dq2, __dqdd3_dq2],
                [__dqdd1_dq3, __dqdd2_dq3, __dqdd3_dq3],
            ]),
            ::planar_arm::__private::columns([
                [__dqdd1_dqd1, __dqdd2_dqd1, __dqdd3_dqd1],
                [__dqdd1_dqd2, __dqdd2_dqd2, __dqdd3_dqd2],
                [__dqdd1_dqd3, __dqdd2_dqd3, __dqdd3_dqd3],
            ]),
            ::planar_arm::__private::columns([
                [__dqdd1_dtau1, __dqdd2_dtau1, __dqdd3_dtau1],
                [__dqdd1_dtau2, __dqdd2_dtau2, __dqdd3_dtau2],
                [__dqdd1_dtau3, __dqdd2_dtau3, __dqdd3_dtau3],
            ]),
        )
    }
    /**qdd = M^-1 (tau - h): M and h = c + g + f from `mass_matrix_and_bias` (one pass), then an L D L^T factorisation of M (no square roots, no allocation) by planar_arm's fixed-size solve, which the compiler unrolls for this arm. Each pivot is floored at 2^-52 times a bound on M_ii (or M_ii itself where it holds run-time parameters), so an ill-conditioned M gives finite accelerations, never infinite or NaN ones.

Cost: 47 multiplications, 44 additions, 3 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn forward_dynamics<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 3>,
        __tau: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 3> {
        let (__m, __h) = self.mass_matrix_and_bias(__q, __qd);
        ::planar_arm::__private::forward_solve(
            &__m,
            __tau,
            &__h,
            [
                ::planar_arm::__private::Floor::Fixed(9.0 / 4503599627370496.0),
                ::planar_arm::__private::Floor::Fixed(1.0 / 1688849860263936.0),
                ::planar_arm::__private::Floor::Fixed(0.00000000000000007401486830834377),
            ],
        )
    }
    #[doc(hidden)]
    type __Frozen = ::planar_arm::__private::Block<0>;
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::PlanarArm<3> for Paper3 {
    const EXACT: ::planar_arm::exact::Derivation<3> = {
        const __NAMES: &[&::core::primitive::str] = &[];
        ::planar_arm::exact::Derivation {
            kinetic_energy: ::planar_arm::__private::terms(
                b"AECBACABGECBBBCBACABCEDBBCCBACABCEDBCBCBACAAKGCABDBABGECBBBCCABDBABCEDBBCCCABDBABCCDBCBCCABDBAACGCABGBABCEDBBCCCABGBABCEDBCBCCABGBAAKMBDCABCEDBCBCBDCAACGCDBGBABCEDBCBCCDBGBAACMBGCA",
                __NAMES,
            ),
            potential_energy: ::planar_arm::__private::terms(
                b"Cq9BwCBBABCAAC+3FwMCBACCAACq9BwMDBADCAA",
                __NAMES,
            ),
            mass_matrix: [
                [
                    ::planar_arm::__private::terms(
                        b"AICAABGCCBBBCAABCCDBBCCAABCCDBCBCAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(
                        b"AKGAABGECBBBCAABCEDBBCCAABCCDBCBCAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(b"ACGAABCEDBBCCAABCEDBCBCAA", __NAMES),
                ],
                [
                    ::planar_arm::__private::terms(
                        b"AKGAABGECBBBCAABCEDBBCCAABCCDBCBCAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(b"AKGAABCCDBCBCAA", __NAMES),
                    ::planar_arm::__private::terms(b"ACGAABCEDBCBCAA", __NAMES),
                ],
                [
                    ::planar_arm::__private::terms(
                        b"ACGAABCEDBBCCAABCEDBCBCAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(b"ACGAABCEDBCBCAA", __NAMES),
                    ::planar_arm::__private::terms(b"ACGAA", __NAMES),
                ],
            ],
            coriolis: [
                ::planar_arm::__private::terms(
                    b"CFCCBBBCCABDBACBCDBBCCCABDBACBCDBBCCCABGBACBCDBCBCCABGBACFECBBBCBDCACBEDBBCCBDCACBCDBBCCCDBGBACBCDBCBCCDBGBACBEDBBCCBGCACBEDBCBCBGCA",
                    __NAMES,
                ),
                ::planar_arm::__private::terms(
                    b"CGECBBBCBACACCEDBBCCBACACBCDBCBCCABGBACBCDBCBCCDBGBACBEDBCBCBGCA",
                    __NAMES,
                ),
                ::planar_arm::__private::terms(
                    b"CCEDBBCCBACACCEDBCBCBACACCCDBCBCCABDBACCEDBCBCBDCA",
                    __NAMES,
                ),
            ],
            gravity: [
                ::planar_arm::__private::terms(
                    b"Bq9BwCBBABCAAB+3FwMCBACCAABq9BwMDBADCAA",
                    __NAMES,
                ),
                ::planar_arm::__private::terms(b"B+3FwMCBACCAABq9BwMDBADCAA", __NAMES),
                ::planar_arm::__private::terms(b"Bq9BwMDBADCAA", __NAMES),
            ],
        }
    };
    ///The joints' names, base first: the order of `q`.
    const JOINT_NAMES: [&'static ::core::primitive::str; 3] = ["upper", "fore", "hand"];
    #[inline]
    fn model(&self) -> ::planar_arm::Model<3> {
        ::planar_arm::Model {
            links: [
                ::planar_arm::Link {
                    length: 1.0,
                    mass: 1.0,
                    inertia: (1.0 / 12.0),
                    com: ::planar_arm::nalgebra::Vector2::new((1.0 / 2.0), 0.0),
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
                    length: 1.0,
                    mass: 1.0,
                    inertia: (1.0 / 12.0),
                    com: ::planar_arm::nalgebra::Vector2::new((1.0 / 2.0), 0.0),
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
                    length: 1.0,
                    mass: 1.0,
                    inertia: (1.0 / 12.0),
                    com: ::planar_arm::nalgebra::Vector2::new((1.0 / 2.0), 0.0),
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
            ],
            gravity: ::planar_arm::nalgebra::Vector2::new(0.0, (-(981.0 / 100.0))),
            payload: ::planar_arm::Payload::NONE,
        }
    }
    /**The tip pose; the orientation is the last link's angle q1 + q2 + q3.

```text
x = c1 + c12 + c123
y = s1 + s12 + s123
```


Cost: 8 multiplications, 8 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn tip_pose(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
    ) -> ::planar_arm::nalgebra::Isometry2<::core::primitive::f64> {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __c12 = __c1 * __c2 - __s1 * __s2;
        let __s12 = __s1 * __c2 + __c1 * __s2;
        let __cos_phi = __c12 * __c3 - __s12 * __s3;
        let __sin_phi = __s12 * __c3 + __c12 * __s3;
        let __x = __cos_phi + __c1 + __c12;
        let __y = __sin_phi + __s1 + __s12;
        ::planar_arm::__private::pose(__x, __y, __cos_phi, __sin_phi)
    }
    /**The Jacobian d(x, y, phi)/dq.

```text
J11 = -s1 - s12 - s123
J12 = -s12 - s123
J13 = -s123
J21 = c1 + c12 + c123
J22 = c12 + c123
J23 = c123
J31 = 1
J32 = 1
J33 = 1
```


Cost: 8 multiplications, 13 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn jacobian<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 3, 3> {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __c12 = __c1 * __c2 - __s1 * __s2;
        let __s12 = __s1 * __c2 + __c1 * __s2;
        let __j23 = __c12 * __c3 - __s12 * __s3;
        let __s123 = __s12 * __c3 + __c12 * __s3;
        let __j11 = -__s1 - (__s12 + __s123);
        let __j12 = -__s12 - __s123;
        let __j13 = -__s123;
        let __j21 = __j23 + __c1 + __c12;
        let __j22 = __c12 + __j23;
        let __j31 = __T::from_f64(1.0);
        ::planar_arm::__private::columns([
            [__j11, __j21, __j31],
            [__j12, __j22, __j31],
            [__j13, __j23, __j31],
        ])
    }
    /**The position of each joint, joint 1 at the origin.

Cost: 4 multiplications, 4 additions, 0 divisions, 2 sin_cos pairs.*/
    #[inline]
    fn joint_positions<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 3>,
    ) -> [::planar_arm::nalgebra::Point2<__T>; 3] {
        let [__q1, __q2, _] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
        ]);
        let __c12 = __c1 * __c2 - __s1 * __s2;
        let __s12 = __s1 * __c2 + __c1 * __s2;
        let __x3 = __c1 + __c12;
        let __y3 = __s1 + __s12;
        let __x1 = __T::from_f64(0.0);
        [
            ::planar_arm::nalgebra::Point2::new(__x1, __x1),
            ::planar_arm::nalgebra::Point2::new(__c1, __s1),
            ::planar_arm::nalgebra::Point2::new(__x3, __y3),
        ]
    }
    /**The tip in polar form: r from r^2 (which does not depend on q1), theta = atan2(y, x).

```text
r^2 = 3 + 2 c2 + 2 c23 + 2 c3
```


Cost: 13 multiplications, 12 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn tip_polar(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
    ) -> (::core::primitive::f64, ::core::primitive::f64) {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __c23 = __c2 * __c3 - __s2 * __s3;
        let __r2 = 3.0 + 2.0 * __c2 + 2.0 * __c23 + 2.0 * __c3;
        let __c12 = __c2 * __c1 - __s2 * __s1;
        let __s12 = __c2 * __s1 + __s2 * __c1;
        let __c123 = __c3 * __c12 - __s3 * __s12;
        let __s123 = __c3 * __s12 + __s3 * __c12;
        let __x = __c123 + __c1 + __c12;
        let __y = __s123 + __s1 + __s12;
        ::planar_arm::__private::polar(__r2, __x, __y)
    }
    /**Statics: tau = J^T (u, v, torque), the motor torques that make the tip exert force (u, v) and torque `torque`.

Cost: 14 multiplications, 19 additions, 0 divisions, 3 sin_cos pairs.*/
    #[inline]
    fn joint_torques(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __force: &::planar_arm::nalgebra::Vector2<::core::primitive::f64>,
        __torque: ::core::primitive::f64,
    ) -> ::planar_arm::nalgebra::SVector<::core::primitive::f64, 3> {
        let [__q1, __q2, __q3] = ::planar_arm::__private::unpack(__q);
        let [__u, __v] = ::planar_arm::__private::unpack(__force);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
        ]);
        let __c12 = __c1 * __c2 - __s1 * __s2;
        let __s12 = __s1 * __c2 + __c1 * __s2;
        let __c123 = __c12 * __c3 - __s12 * __s3;
        let __s123 = __s12 * __c3 + __c12 * __s3;
        let __tau1 = __torque + __u * (-__s1 - (__s12 + __s123))
            + __v * (__c123 + __c1 + __c12);
        let __tau2 = __torque + __u * (-__s12 - __s123) + __v * (__c12 + __c123);
        let __tau3 = __torque + __u * (-__s123) + __v * __c123;
        ::planar_arm::__private::vector([__tau1, __tau2, __tau3])
    }
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::kinematics::ClosedFormIk<3> for Paper3 {
    type Target = ::planar_arm::nalgebra::Isometry2<::core::primitive::f64>;
    /// Through the wrist point, as in the paper: the two-link solution for
    /// (x - l3 cos phi, y - l3 sin phi), then q3 = phi - q1 - q2.
    #[inline]
    fn inverse_kinematics(
        &self,
        __target: &::planar_arm::nalgebra::Isometry2<::core::primitive::f64>,
    ) -> ::core::result::Result<
        [::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>; 2],
        ::planar_arm::ArmError,
    > {
        ::planar_arm::kinematics::ik3(1.0, 1.0, 1.0, __target)
    }
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::kinematics::TipWrench for Paper3 {
    #[inline]
    fn tip_wrench(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 3>,
    ) -> ::core::result::Result<
        ::planar_arm::kinematics::StaticWrench<3>,
        ::planar_arm::ArmError,
    > {
        ::planar_arm::kinematics::tip_wrench3(1.0, 1.0, 1.0, __q, __tau)
    }
}
