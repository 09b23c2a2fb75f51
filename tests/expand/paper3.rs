#[automatically_derived]
impl ::planar_arm::PlanarArm<3> for Paper3 {
    const LINKS: [::planar_arm::Link; 3] = [
        ::planar_arm::Link {
            length: 1.0,
            mass: 1.0,
            inertia: (1.0 / 12.0),
            com: (1.0 / 2.0),
        },
        ::planar_arm::Link {
            length: 1.0,
            mass: 1.0,
            inertia: (1.0 / 12.0),
            com: (1.0 / 2.0),
        },
        ::planar_arm::Link {
            length: 1.0,
            mass: 1.0,
            inertia: (1.0 / 12.0),
            com: (1.0 / 2.0),
        },
    ];
    const GRAVITY: f64 = (981.0 / 100.0);
    const EXACT: ::planar_arm::exact::Derivation<3> = ::planar_arm::exact::Derivation {
        kinetic_energy: &[
            ::planar_arm::__private::term(
                2,
                1,
                0,
                &[],
                &[(::planar_arm::__private::Qd(0), 2)],
            ),
            ::planar_arm::__private::term(
                3,
                2,
                1,
                &[0, 1],
                &[(::planar_arm::__private::Qd(0), 2)],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 1, 1],
                &[(::planar_arm::__private::Qd(0), 2)],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 0, 1],
                &[(::planar_arm::__private::Qd(0), 2)],
            ),
            ::planar_arm::__private::term(
                5,
                3,
                0,
                &[],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(1), 1),
                ],
            ),
            ::planar_arm::__private::term(
                3,
                2,
                1,
                &[0, 1],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(1), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 1, 1],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(1), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
                1,
                1,
                &[0, 0, 1],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(1), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
                3,
                0,
                &[],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(2), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 1, 1],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(2), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 0, 1],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(2), 1),
                ],
            ),
            ::planar_arm::__private::term(
                5,
                6,
                0,
                &[],
                &[(::planar_arm::__private::Qd(1), 2)],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 0, 1],
                &[(::planar_arm::__private::Qd(1), 2)],
            ),
            ::planar_arm::__private::term(
                1,
                3,
                0,
                &[],
                &[
                    (::planar_arm::__private::Qd(1), 1),
                    (::planar_arm::__private::Qd(2), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 0, 1],
                &[
                    (::planar_arm::__private::Qd(1), 1),
                    (::planar_arm::__private::Qd(2), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
                6,
                0,
                &[],
                &[(::planar_arm::__private::Qd(2), 2)],
            ),
        ],
        potential_energy: &[
            ::planar_arm::__private::term(981, 40, 2, &[1], &[]),
            ::planar_arm::__private::term(2943, 200, 2, &[1, 1], &[]),
            ::planar_arm::__private::term(981, 200, 2, &[1, 1, 1], &[]),
        ],
        mass_matrix: [
            [
                &[
                    ::planar_arm::__private::term(4, 1, 0, &[], &[]),
                    ::planar_arm::__private::term(3, 1, 1, &[0, 1], &[]),
                    ::planar_arm::__private::term(1, 1, 1, &[0, 1, 1], &[]),
                    ::planar_arm::__private::term(1, 1, 1, &[0, 0, 1], &[]),
                ],
                &[
                    ::planar_arm::__private::term(5, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(3, 2, 1, &[0, 1], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 1, 1], &[]),
                    ::planar_arm::__private::term(1, 1, 1, &[0, 0, 1], &[]),
                ],
                &[
                    ::planar_arm::__private::term(1, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 1, 1], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 0, 1], &[]),
                ],
            ],
            [
                &[
                    ::planar_arm::__private::term(5, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(3, 2, 1, &[0, 1], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 1, 1], &[]),
                    ::planar_arm::__private::term(1, 1, 1, &[0, 0, 1], &[]),
                ],
                &[
                    ::planar_arm::__private::term(5, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 1, 1, &[0, 0, 1], &[]),
                ],
                &[
                    ::planar_arm::__private::term(1, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 0, 1], &[]),
                ],
            ],
            [
                &[
                    ::planar_arm::__private::term(1, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 1, 1], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 0, 1], &[]),
                ],
                &[
                    ::planar_arm::__private::term(1, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 0, 1], &[]),
                ],
                &[::planar_arm::__private::term(1, 3, 0, &[], &[])],
            ],
        ],
        coriolis: [
            &[
                ::planar_arm::__private::term(
                    -3,
                    1,
                    2,
                    &[0, 1],
                    &[
                        (::planar_arm::__private::Qd(0), 1),
                        (::planar_arm::__private::Qd(1), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -1,
                    1,
                    2,
                    &[0, 1, 1],
                    &[
                        (::planar_arm::__private::Qd(0), 1),
                        (::planar_arm::__private::Qd(1), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -1,
                    1,
                    2,
                    &[0, 1, 1],
                    &[
                        (::planar_arm::__private::Qd(0), 1),
                        (::planar_arm::__private::Qd(2), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -1,
                    1,
                    2,
                    &[0, 0, 1],
                    &[
                        (::planar_arm::__private::Qd(0), 1),
                        (::planar_arm::__private::Qd(2), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -3,
                    2,
                    2,
                    &[0, 1],
                    &[(::planar_arm::__private::Qd(1), 2)],
                ),
                ::planar_arm::__private::term(
                    -1,
                    2,
                    2,
                    &[0, 1, 1],
                    &[(::planar_arm::__private::Qd(1), 2)],
                ),
                ::planar_arm::__private::term(
                    -1,
                    1,
                    2,
                    &[0, 1, 1],
                    &[
                        (::planar_arm::__private::Qd(1), 1),
                        (::planar_arm::__private::Qd(2), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -1,
                    1,
                    2,
                    &[0, 0, 1],
                    &[
                        (::planar_arm::__private::Qd(1), 1),
                        (::planar_arm::__private::Qd(2), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -1,
                    2,
                    2,
                    &[0, 1, 1],
                    &[(::planar_arm::__private::Qd(2), 2)],
                ),
                ::planar_arm::__private::term(
                    -1,
                    2,
                    2,
                    &[0, 0, 1],
                    &[(::planar_arm::__private::Qd(2), 2)],
                ),
            ],
            &[
                ::planar_arm::__private::term(
                    3,
                    2,
                    2,
                    &[0, 1],
                    &[(::planar_arm::__private::Qd(0), 2)],
                ),
                ::planar_arm::__private::term(
                    1,
                    2,
                    2,
                    &[0, 1, 1],
                    &[(::planar_arm::__private::Qd(0), 2)],
                ),
                ::planar_arm::__private::term(
                    -1,
                    1,
                    2,
                    &[0, 0, 1],
                    &[
                        (::planar_arm::__private::Qd(0), 1),
                        (::planar_arm::__private::Qd(2), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -1,
                    1,
                    2,
                    &[0, 0, 1],
                    &[
                        (::planar_arm::__private::Qd(1), 1),
                        (::planar_arm::__private::Qd(2), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    -1,
                    2,
                    2,
                    &[0, 0, 1],
                    &[(::planar_arm::__private::Qd(2), 2)],
                ),
            ],
            &[
                ::planar_arm::__private::term(
                    1,
                    2,
                    2,
                    &[0, 1, 1],
                    &[(::planar_arm::__private::Qd(0), 2)],
                ),
                ::planar_arm::__private::term(
                    1,
                    2,
                    2,
                    &[0, 0, 1],
                    &[(::planar_arm::__private::Qd(0), 2)],
                ),
                ::planar_arm::__private::term(
                    1,
                    1,
                    2,
                    &[0, 0, 1],
                    &[
                        (::planar_arm::__private::Qd(0), 1),
                        (::planar_arm::__private::Qd(1), 1),
                    ],
                ),
                ::planar_arm::__private::term(
                    1,
                    2,
                    2,
                    &[0, 0, 1],
                    &[(::planar_arm::__private::Qd(1), 2)],
                ),
            ],
        ],
        gravity: [
            &[
                ::planar_arm::__private::term(981, 40, 1, &[1], &[]),
                ::planar_arm::__private::term(2943, 200, 1, &[1, 1], &[]),
                ::planar_arm::__private::term(981, 200, 1, &[1, 1, 1], &[]),
            ],
            &[
                ::planar_arm::__private::term(2943, 200, 1, &[1, 1], &[]),
                ::planar_arm::__private::term(981, 200, 1, &[1, 1, 1], &[]),
            ],
            &[::planar_arm::__private::term(981, 200, 1, &[1, 1, 1], &[])],
        ],
    };
    /**The mass matrix M(q), derived exactly (symmetric; upper triangle shown). Joint angles `q`, rates `qd`, accelerations `qdd` (1-based in the formulas); `cK` and `sK...` are the cosine and sine of the sum of the joint angles named by the digits.

```text
M11 = 4 + 3 c2 + c23 + c3
M12 = 5/3 + 3/2 c2 + 1/2 c23 + c3
M13 = 1/3 + 1/2 c23 + 1/2 c3
M22 = 5/3 + c3
M23 = 1/3 + 1/2 c3
M33 = 1/3
```


Cost: 6 multiplications, 11 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn mass_matrix(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::SMatrix<f64, 3, 3> {
        let _ = (&self.upper, &self.fore, &self.hand);
        let [_, q2, q3] = ::planar_arm::__private::unpack(q);
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c23 = c2 * c3 - s2 * s3;
        let m11 = c3 + c23 + 4.0 + 3.0 * c2;
        let t1 = (1.0 / 2.0) * c23;
        let m12 = c3 + t1 + (5.0 / 3.0) + (3.0 / 2.0) * c2;
        let t2 = (1.0 / 2.0) * c3;
        let m13 = t2 + t1 + (1.0 / 3.0);
        let m22 = c3 + (5.0 / 3.0);
        let m23 = (1.0 / 3.0) + t2;
        let m33 = (1.0 / 3.0);
        ::planar_arm::__private::matrix([
            [m11, m12, m13],
            [m12, m22, m23],
            [m13, m23, m33],
        ])
    }
    /**The velocity-product torques c(q, qd).

```text
c1 = (-3 s2 - s23) qd1 qd2 + (-s23 - s3) qd1 qd3 + (-3/2 s2 - 1/2 s23) qd2^2 + (-s23 - s3) qd2 qd3 + (-1/2 s23 - 1/2 s3) qd3^2
c2 = (3/2 s2 + 1/2 s23) qd1^2 - s3 qd1 qd3 - s3 qd2 qd3 - 1/2 s3 qd3^2
c3 = (1/2 s23 + 1/2 s3) qd1^2 + s3 qd1 qd2 + 1/2 s3 qd2^2
```


Cost: 24 multiplications, 20 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn coriolis(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
        qd: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 3> {
        let [_, q2, q3] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2, qd3] = ::planar_arm::__private::unpack(qd);
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let s23 = s2 * c3 + c2 * s3;
        let t1 = qd1 * qd2;
        let t2 = -s23 - s3;
        let t3 = qd1 * qd3;
        let t4 = (3.0 / 2.0) * s2;
        let t5 = (1.0 / 2.0) * s23;
        let t6 = qd2 * qd2;
        let t7 = qd2 * qd3;
        let t8 = (1.0 / 2.0) * s3;
        let t9 = qd3 * qd3;
        let cor1 = (-t5 - t8) * t9 + t2 * t7 + (-t4 - t5) * t6 + (-(3.0 * s2) - s23) * t1
            + t2 * t3;
        let t10 = qd1 * qd1;
        let cor2 = (t4 + t5) * t10 - s3 * t3 - s3 * t7 - t8 * t9;
        let cor3 = t6 * t8 + t10 * (t5 + t8) + s3 * t1;
        ::planar_arm::__private::vector([cor1, cor2, cor3])
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


Cost: 15 multiplications, 19 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn coriolis_matrix(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
        qd: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::SMatrix<f64, 3, 3> {
        let [_, q2, q3] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2, qd3] = ::planar_arm::__private::unpack(qd);
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let t1 = (3.0 / 2.0) * s2;
        let s23 = s2 * c3 + c2 * s3;
        let t2 = (1.0 / 2.0) * s23;
        let t3 = -t1 - t2;
        let t4 = t3 * qd2;
        let t5 = (1.0 / 2.0) * s3;
        let t6 = -t2 - t5;
        let t7 = t6 * qd3;
        let cm11 = t4 + t7;
        let cm12 = t7 + t4 + t3 * qd1;
        let cm13 = t7 + t6 * qd1 + qd2 * t6;
        let t8 = t5 * qd3;
        let cm21 = qd1 * (t1 + t2) - t8;
        let cm22 = -t8;
        let t9 = t5 * qd1;
        let t10 = qd2 * t5;
        let cm23 = -t9 - t10 - t8;
        let cm31 = t10 + qd1 * (t2 + t5);
        let cm32 = t9 + t10;
        let cm33 = 0.0;
        ::planar_arm::__private::matrix([
            [cm11, cm12, cm13],
            [cm21, cm22, cm23],
            [cm31, cm32, cm33],
        ])
    }
    /**The gravity torques g(q) = dV/dq.

```text
g1 = 981/40 c1 + 2943/200 c12 + 981/200 c123
g2 = 2943/200 c12 + 981/200 c123
g3 = 981/200 c123
```


Cost: 9 multiplications, 6 additions, 0 divisions, 3 sin_cos calls.*/
    #[inline]
    fn gravity(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 3> {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let t1 = (2943.0 / 200.0) * c12;
        let c123 = c12 * c3 - s12 * s3;
        let g3 = (981.0 / 200.0) * c123;
        let g1 = g3 + (981.0 / 40.0) * c1 + t1;
        let g2 = t1 + g3;
        ::planar_arm::__private::vector([g1, g2, g3])
    }
    /**Lagrange's equation, tau_i = d/dt dL/dqd_i - dL/dq_i, expanded.

```text
tau1 = (981/40 c1 + 2943/200 c12 + 981/200 c123) + (4 + 3 c2 + c23 + c3) qdd1 + (5/3 + 3/2 c2 + 1/2 c23 + c3) qdd2 + (1/3 + 1/2 c23 + 1/2 c3) qdd3 + (-3 s2 - s23) qd1 qd2 + (-s23 - s3) qd1 qd3 + (-3/2 s2 - 1/2 s23) qd2^2 + (-s23 - s3) qd2 qd3 + (-1/2 s23 - 1/2 s3) qd3^2
tau2 = (2943/200 c12 + 981/200 c123) + (5/3 + 3/2 c2 + 1/2 c23 + c3) qdd1 + (5/3 + c3) qdd2 + (1/3 + 1/2 c3) qdd3 + (3/2 s2 + 1/2 s23) qd1^2 - s3 qd1 qd3 - s3 qd2 qd3 - 1/2 s3 qd3^2
tau3 = 981/200 c123 + (1/3 + 1/2 c23 + 1/2 c3) qdd1 + (1/3 + 1/2 c3) qdd2 + 1/3 qdd3 + (1/2 s23 + 1/2 s3) qd1^2 + s3 qd1 qd2 + 1/2 s3 qd2^2
```


Cost: 48 multiplications, 49 additions, 0 divisions, 3 sin_cos calls.*/
    #[inline]
    fn inverse_dynamics(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
        qd: &::planar_arm::nalgebra::SVector<f64, 3>,
        qdd: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 3> {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2, qd3] = ::planar_arm::__private::unpack(qd);
        let [qdd1, qdd2, qdd3] = ::planar_arm::__private::unpack(qdd);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let t1 = (2943.0 / 200.0) * c12;
        let c123 = c12 * c3 - s12 * s3;
        let t2 = (981.0 / 200.0) * c123;
        let c23 = c2 * c3 - s2 * s3;
        let s23 = s2 * c3 + c2 * s3;
        let t3 = (1.0 / 2.0) * c23;
        let t4 = c3 + t3 + (5.0 / 3.0) + (3.0 / 2.0) * c2;
        let t5 = (1.0 / 2.0) * c3;
        let t6 = t5 + t3 + (1.0 / 3.0);
        let t7 = qd1 * qd2;
        let t8 = -s23 - s3;
        let t9 = qd1 * qd3;
        let t10 = (3.0 / 2.0) * s2;
        let t11 = (1.0 / 2.0) * s23;
        let t12 = qd2 * qd2;
        let t13 = qd2 * qd3;
        let t14 = (1.0 / 2.0) * s3;
        let t15 = qd3 * qd3;
        let tau1 = (-t11 - t14) * t15 + t8 * t13 + (-t10 - t11) * t12 + t8 * t9
            + (-(3.0 * s2) - s23) * t7 + t6 * qdd3 + t4 * qdd2 + t2 + (981.0 / 40.0) * c1
            + t1 + (c3 + c23 + 4.0 + 3.0 * c2) * qdd1;
        let t16 = (1.0 / 3.0) + t5;
        let t17 = qd1 * qd1;
        let tau2 = (t10 + t11) * t17 + qdd3 * t16 + qdd2 * (c3 + (5.0 / 3.0)) + t1 + t2
            + qdd1 * t4 - s3 * t9 - s3 * t13 - t14 * t15;
        let tau3 = t12 * t14 + s3 * t7 + t17 * (t11 + t14) + (1.0 / 3.0) * qdd3
            + qdd2 * t16 + t2 + qdd1 * t6;
        ::planar_arm::__private::vector([tau1, tau2, tau3])
    }
    /**qdd = M^-1 (tau - c - g) by an unrolled L D L^T factorisation of M (no square roots, no allocation).

Cost: 59 multiplications, 53 additions, 3 divisions, 3 sin_cos calls.*/
    #[inline]
    fn forward_dynamics(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
        qd: &::planar_arm::nalgebra::SVector<f64, 3>,
        tau: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 3> {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2, qd3] = ::planar_arm::__private::unpack(qd);
        let [tau1, tau2, tau3] = ::planar_arm::__private::unpack(tau);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c23 = c2 * c3 - s2 * s3;
        let s23 = s2 * c3 + c2 * s3;
        let d1 = c3 + c23 + 4.0 + 3.0 * c2;
        let t1 = (1.0 / 2.0) * c23;
        let t2 = (1.0 / 2.0) * c3;
        let c12 = c2 * c1 - s2 * s1;
        let s12 = c2 * s1 + s2 * c1;
        let t3 = (2943.0 / 200.0) * c12;
        let c123 = c3 * c12 - s3 * s12;
        let t4 = (981.0 / 200.0) * c123;
        let t5 = qd1 * qd2;
        let t6 = -s23 - s3;
        let t7 = qd1 * qd3;
        let t8 = (3.0 / 2.0) * s2;
        let t9 = (1.0 / 2.0) * s23;
        let t10 = qd2 * qd2;
        let t11 = qd2 * qd3;
        let t12 = (1.0 / 2.0) * s3;
        let t13 = qd3 * qd3;
        let rhs1 = tau1
            - ((-t9 - t12) * t13 + t6 * t11 + (-t8 - t9) * t10 + t6 * t7 + t4
                + (981.0 / 40.0) * c1 + t3 + (-(3.0 * s2) - s23) * t5);
        let t14 = qd1 * qd1;
        let rhs2 = tau2 - (t3 + t4 + (t8 + t9) * t14 - s3 * t7 - s3 * t11 - t12 * t13);
        let rhs3 = tau3 - (t10 * t12 + s3 * t5 + t4 + t14 * (t9 + t12));
        let inv_d1 = 1.0 / d1;
        let l21 = (c3 + t1 + (5.0 / 3.0) + (3.0 / 2.0) * c2) * inv_d1;
        let l31 = (t2 + t1 + (1.0 / 3.0)) * inv_d1;
        let d2 = c3 + (5.0 / 3.0) - d1 * l21 * l21;
        let inv_d2 = 1.0 / d2;
        let l32 = inv_d2 * ((1.0 / 3.0) + t2 - d1 * l21 * l31);
        let d3 = (1.0 / 3.0) - d1 * l31 * l31 - d2 * l32 * l32;
        let inv_d3 = 1.0 / d3;
        let t15 = rhs2 - rhs1 * l21;
        let qdd3 = inv_d3 * (rhs3 - rhs1 * l31 - l32 * t15);
        let qdd2 = inv_d2 * t15 - l32 * qdd3;
        let qdd1 = rhs1 * inv_d1 - l21 * qdd2 - l31 * qdd3;
        ::planar_arm::__private::vector([qdd1, qdd2, qdd3])
    }
    /**The kinetic energy.

```text
T = (2 + 3/2 c2 + 1/2 c23 + 1/2 c3) qd1^2 + (5/3 + 3/2 c2 + 1/2 c23 + c3) qd1 qd2 + (1/3 + 1/2 c23 + 1/2 c3) qd1 qd3 + (5/6 + 1/2 c3) qd2^2 + (1/3 + 1/2 c3) qd2 qd3 + 1/6 qd3^2
```


Cost: 17 multiplications, 16 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn kinetic_energy(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
        qd: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> f64 {
        let [_, q2, q3] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2, qd3] = ::planar_arm::__private::unpack(qd);
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let t1 = (3.0 / 2.0) * c2;
        let c23 = c2 * c3 - s2 * s3;
        let t2 = (1.0 / 2.0) * c23;
        let t3 = (1.0 / 2.0) * c3;
        let kinetic = (1.0 / 6.0) * qd3 * qd3 + (t3 + (1.0 / 3.0)) * qd2 * qd3
            + (t3 + (5.0 / 6.0)) * qd2 * qd2 + (t3 + t2 + (1.0 / 3.0)) * qd1 * qd3
            + (t3 + t2 + 2.0 + t1) * qd1 * qd1
            + (c3 + t2 + t1 + (5.0 / 3.0)) * qd1 * qd2;
        kinetic
    }
    /**The potential energy (zero at y = 0).

```text
V = 981/40 s1 + 2943/200 s12 + 981/200 s123
```


Cost: 9 multiplications, 5 additions, 0 divisions, 3 sin_cos calls.*/
    #[inline]
    fn potential_energy(&self, q: &::planar_arm::nalgebra::SVector<f64, 3>) -> f64 {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let s123 = s12 * c3 + c12 * s3;
        let potential = (981.0 / 200.0) * s123 + (981.0 / 40.0) * s1
            + (2943.0 / 200.0) * s12;
        potential
    }
    /**The tip pose; the orientation is the last link's angle q1 + q2 + q3.

```text
x = c1 + c12 + c123
y = s1 + s12 + s123
```


Cost: 8 multiplications, 8 additions, 0 divisions, 3 sin_cos calls.*/
    #[inline]
    fn tip_pose(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::Isometry2<f64> {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let cos_phi = c12 * c3 - s12 * s3;
        let sin_phi = s12 * c3 + c12 * s3;
        let x = cos_phi + c1 + c12;
        let y = sin_phi + s1 + s12;
        ::planar_arm::__private::pose(x, y, cos_phi, sin_phi)
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


Cost: 8 multiplications, 13 additions, 0 divisions, 3 sin_cos calls.*/
    #[inline]
    fn jacobian(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::planar_arm::nalgebra::SMatrix<f64, 3, 3> {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let j23 = c12 * c3 - s12 * s3;
        let s123 = s12 * c3 + c12 * s3;
        let j11 = -s1 - s12 - s123;
        let j12 = -s12 - s123;
        let j13 = -s123;
        let j21 = j23 + c1 + c12;
        let j22 = c12 + j23;
        let j31 = 1.0;
        ::planar_arm::__private::matrix([
            [j11, j12, j13],
            [j21, j22, j23],
            [j31, j31, j31],
        ])
    }
    /**The position of each joint, joint 1 at the origin.

Cost: 4 multiplications, 4 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn joint_positions(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> [::planar_arm::nalgebra::Point2<f64>; 3] {
        let [q1, q2, _] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let x3 = c1 + c12;
        let y3 = s1 + s12;
        let x1 = 0.0;
        [
            ::planar_arm::nalgebra::Point2::new(x1, x1),
            ::planar_arm::nalgebra::Point2::new(c1, s1),
            ::planar_arm::nalgebra::Point2::new(x3, y3),
        ]
    }
    /**The tip in polar form: r from r^2 (which does not depend on q1), theta = atan2(y, x).

```text
r^2 = 3 + 2 c2 + 2 c23 + 2 c3
```


Cost: 13 multiplications, 12 additions, 0 divisions, 3 sin_cos calls.*/
    #[inline]
    fn tip_polar(&self, q: &::planar_arm::nalgebra::SVector<f64, 3>) -> (f64, f64) {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c23 = c2 * c3 - s2 * s3;
        let r2 = 2.0 * c3 + 2.0 * c23 + 3.0 + 2.0 * c2;
        let c12 = c2 * c1 - s2 * s1;
        let s12 = c2 * s1 + s2 * c1;
        let c123 = c3 * c12 - s3 * s12;
        let s123 = c3 * s12 + s3 * c12;
        let x = c123 + c1 + c12;
        let y = s123 + s1 + s12;
        ::planar_arm::__private::polar(r2, x, y)
    }
    /**Statics: tau = J^T (u, v, torque), the motor torques that make the tip exert force (u, v) and torque `torque`.

Cost: 14 multiplications, 19 additions, 0 divisions, 3 sin_cos calls.*/
    #[inline]
    fn joint_torques(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
        force: &::planar_arm::nalgebra::Vector2<f64>,
        torque: f64,
    ) -> ::planar_arm::nalgebra::SVector<f64, 3> {
        let [q1, q2, q3] = ::planar_arm::__private::unpack(q);
        let [u, v] = ::planar_arm::__private::unpack(force);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let (s3, c3) = q3.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let c123 = c12 * c3 - s12 * s3;
        let s123 = s12 * c3 + c12 * s3;
        let tau1 = torque + u * (-s1 - s12 - s123) + v * (c123 + c1 + c12);
        let tau2 = torque + u * (-s12 - s123) + v * (c12 + c123);
        let tau3 = torque + u * (-s123) + v * c123;
        ::planar_arm::__private::vector([tau1, tau2, tau3])
    }
}
#[automatically_derived]
impl ::planar_arm::kinematics::ClosedFormIk<3> for Paper3 {
    type Target = ::planar_arm::nalgebra::Isometry2<f64>;
    /// Through the wrist point, as in the paper: the two-link solution for
    /// (x - l3 cos phi, y - l3 sin phi), then q3 = phi - q1 - q2.
    #[inline]
    fn inverse_kinematics(
        &self,
        target: &::planar_arm::nalgebra::Isometry2<f64>,
    ) -> ::core::result::Result<
        [::planar_arm::nalgebra::SVector<f64, 3>; 2],
        ::planar_arm::ArmError,
    > {
        ::planar_arm::kinematics::ik3(1.0, 1.0, 1.0, target)
    }
}
#[automatically_derived]
impl ::planar_arm::kinematics::TipWrench for Paper3 {
    #[inline]
    fn tip_wrench(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 3>,
        tau: &::planar_arm::nalgebra::SVector<f64, 3>,
    ) -> ::core::result::Result<
        (::planar_arm::nalgebra::Vector2<f64>, f64),
        ::planar_arm::ArmError,
    > {
        ::planar_arm::kinematics::tip_wrench3(1.0, 1.0, 1.0, q, tau)
    }
}
