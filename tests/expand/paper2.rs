#[automatically_derived]
impl ::planar_arm::PlanarArm<2> for Paper2 {
    const LINKS: [::planar_arm::Link; 2] = [
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
    const EXACT: ::planar_arm::exact::Derivation<2> = ::planar_arm::exact::Derivation {
        kinetic_energy: &[
            ::planar_arm::__private::term(
                5,
                6,
                0,
                &[],
                &[(::planar_arm::__private::Qd(0), 2)],
            ),
            ::planar_arm::__private::term(
                1,
                2,
                1,
                &[0, 1],
                &[(::planar_arm::__private::Qd(0), 2)],
            ),
            ::planar_arm::__private::term(
                1,
                3,
                0,
                &[],
                &[
                    (::planar_arm::__private::Qd(0), 1),
                    (::planar_arm::__private::Qd(1), 1),
                ],
            ),
            ::planar_arm::__private::term(
                1,
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
                6,
                0,
                &[],
                &[(::planar_arm::__private::Qd(1), 2)],
            ),
        ],
        potential_energy: &[
            ::planar_arm::__private::term(2943, 200, 2, &[1], &[]),
            ::planar_arm::__private::term(981, 200, 2, &[1, 1], &[]),
        ],
        mass_matrix: [
            [
                &[
                    ::planar_arm::__private::term(5, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 1, 1, &[0, 1], &[]),
                ],
                &[
                    ::planar_arm::__private::term(1, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 1], &[]),
                ],
            ],
            [
                &[
                    ::planar_arm::__private::term(1, 3, 0, &[], &[]),
                    ::planar_arm::__private::term(1, 2, 1, &[0, 1], &[]),
                ],
                &[::planar_arm::__private::term(1, 3, 0, &[], &[])],
            ],
        ],
        coriolis: [
            &[
                ::planar_arm::__private::term(
                    -1,
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
                    2,
                    2,
                    &[0, 1],
                    &[(::planar_arm::__private::Qd(1), 2)],
                ),
            ],
            &[
                ::planar_arm::__private::term(
                    1,
                    2,
                    2,
                    &[0, 1],
                    &[(::planar_arm::__private::Qd(0), 2)],
                ),
            ],
        ],
        gravity: [
            &[
                ::planar_arm::__private::term(2943, 200, 1, &[1], &[]),
                ::planar_arm::__private::term(981, 200, 1, &[1, 1], &[]),
            ],
            &[::planar_arm::__private::term(981, 200, 1, &[1, 1], &[])],
        ],
    };
    /**The mass matrix M(q), derived exactly (symmetric; upper triangle shown). Joint angles `q`, rates `qd`, accelerations `qdd` (1-based in the formulas); `cK` and `sK...` are the cosine and sine of the sum of the joint angles named by the digits.

```text
M11 = 5/3 + c2
M12 = 1/3 + 1/2 c2
M22 = 1/3
```


Cost: 1 multiplications, 2 additions, 0 divisions, 1 sin_cos calls.*/
    #[inline]
    fn mass_matrix(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::SMatrix<f64, 2, 2> {
        let _ = (&self.upper, &self.fore);
        let [_, q2] = ::planar_arm::__private::unpack(q);
        let (_, c2) = q2.sin_cos();
        let m11 = (5.0 / 3.0) + c2;
        let m12 = (1.0 / 3.0) + (1.0 / 2.0) * c2;
        let m22 = (1.0 / 3.0);
        ::planar_arm::__private::matrix([[m11, m12], [m12, m22]])
    }
    /**The velocity-product torques c(q, qd).

```text
c1 = -s2 qd1 qd2 - 1/2 s2 qd2^2
c2 = 1/2 s2 qd1^2
```


Cost: 7 multiplications, 2 additions, 0 divisions, 1 sin_cos calls.*/
    #[inline]
    fn coriolis(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
        qd: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 2> {
        let [_, q2] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2] = ::planar_arm::__private::unpack(qd);
        let (s2, _) = q2.sin_cos();
        let t1 = (1.0 / 2.0) * s2;
        let cor1 = -(s2 * qd1 * qd2) - t1 * qd2 * qd2;
        let cor2 = t1 * qd1 * qd1;
        ::planar_arm::__private::vector([cor1, cor2])
    }
    /**The Coriolis matrix from Christoffel symbols, C_ij = sum_k 1/2 (dM_ij/dq_k + dM_ik/dq_j - dM_jk/dq_i) qd_k.

```text
C11 = -1/2 s2 qd2
C12 = -1/2 s2 qd1 - 1/2 s2 qd2
C21 = 1/2 s2 qd1
C22 = 0
```


Cost: 3 multiplications, 3 additions, 0 divisions, 1 sin_cos calls.*/
    #[inline]
    fn coriolis_matrix(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
        qd: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::SMatrix<f64, 2, 2> {
        let [_, q2] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2] = ::planar_arm::__private::unpack(qd);
        let (s2, _) = q2.sin_cos();
        let t1 = (1.0 / 2.0) * s2;
        let t2 = t1 * qd2;
        let cm11 = -t2;
        let cm21 = t1 * qd1;
        let cm12 = -cm21 - t2;
        let cm22 = 0.0;
        ::planar_arm::__private::matrix([[cm11, cm12], [cm21, cm22]])
    }
    /**The gravity torques g(q) = dV/dq.

```text
g1 = 2943/200 c1 + 981/200 c12
g2 = 981/200 c12
```


Cost: 4 multiplications, 2 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn gravity(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 2> {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let g2 = (981.0 / 200.0) * c12;
        let g1 = (2943.0 / 200.0) * c1 + g2;
        ::planar_arm::__private::vector([g1, g2])
    }
    /**Lagrange's equation, tau_i = d/dt dL/dqd_i - dL/dq_i, expanded.

```text
tau1 = (2943/200 c1 + 981/200 c12) + (5/3 + c2) qdd1 + (1/3 + 1/2 c2) qdd2 - s2 qd1 qd2 - 1/2 s2 qd2^2
tau2 = 981/200 c12 + (1/3 + 1/2 c2) qdd1 + 1/3 qdd2 + 1/2 s2 qd1^2
```


Cost: 16 multiplications, 11 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn inverse_dynamics(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
        qd: &::planar_arm::nalgebra::SVector<f64, 2>,
        qdd: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 2> {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2] = ::planar_arm::__private::unpack(qd);
        let [qdd1, qdd2] = ::planar_arm::__private::unpack(qdd);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let t1 = (981.0 / 200.0) * c12;
        let t2 = (1.0 / 3.0) + (1.0 / 2.0) * c2;
        let t3 = (1.0 / 2.0) * s2;
        let tau1 = t2 * qdd2 + (2943.0 / 200.0) * c1 + t1 + (c2 + (5.0 / 3.0)) * qdd1
            - s2 * qd1 * qd2 - t3 * qd2 * qd2;
        let tau2 = t3 * qd1 * qd1 + (1.0 / 3.0) * qdd2 + t1 + qdd1 * t2;
        ::planar_arm::__private::vector([tau1, tau2])
    }
    /**qdd = M^-1 (tau - c - g) in closed form (Cramer's rule, det = M11 M22 - M12^2 > 0).

Cost: 18 multiplications, 12 additions, 2 divisions, 2 sin_cos calls.*/
    #[inline]
    fn forward_dynamics(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
        qd: &::planar_arm::nalgebra::SVector<f64, 2>,
        tau: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::SVector<f64, 2> {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2] = ::planar_arm::__private::unpack(qd);
        let [tau1, tau2] = ::planar_arm::__private::unpack(tau);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let t1 = (5.0 / 3.0) + c2;
        let t2 = (1.0 / 3.0) + (1.0 / 2.0) * c2;
        let c12 = c2 * c1 - s2 * s1;
        let t3 = (981.0 / 200.0) * c12;
        let t4 = (1.0 / 2.0) * s2;
        let rhs1 = tau1 - ((2943.0 / 200.0) * c1 + t3 - s2 * qd1 * qd2 - t4 * qd2 * qd2);
        let rhs2 = tau2 - (t3 + t4 * qd1 * qd1);
        let det = (1.0 / 3.0) * t1 - t2 * t2;
        let qdd1 = ((1.0 / 3.0) * rhs1 - t2 * rhs2) / det;
        let qdd2 = (t1 * rhs2 - t2 * rhs1) / det;
        ::planar_arm::__private::vector([qdd1, qdd2])
    }
    /**The kinetic energy.

```text
T = (5/6 + 1/2 c2) qd1^2 + (1/3 + 1/2 c2) qd1 qd2 + 1/6 qd2^2
```


Cost: 7 multiplications, 4 additions, 0 divisions, 1 sin_cos calls.*/
    #[inline]
    fn kinetic_energy(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
        qd: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> f64 {
        let [_, q2] = ::planar_arm::__private::unpack(q);
        let [qd1, qd2] = ::planar_arm::__private::unpack(qd);
        let (_, c2) = q2.sin_cos();
        let t1 = (1.0 / 2.0) * c2;
        let kinetic = (1.0 / 6.0) * qd2 * qd2 + ((5.0 / 6.0) + t1) * qd1 * qd1
            + (t1 + (1.0 / 3.0)) * qd1 * qd2;
        kinetic
    }
    /**The potential energy (zero at y = 0).

```text
V = 2943/200 s1 + 981/200 s12
```


Cost: 4 multiplications, 2 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn potential_energy(&self, q: &::planar_arm::nalgebra::SVector<f64, 2>) -> f64 {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let s12 = s1 * c2 + c1 * s2;
        let potential = (2943.0 / 200.0) * s1 + (981.0 / 200.0) * s12;
        potential
    }
    /**The tip pose; the orientation is the last link's angle q1 + q2.

```text
x = c1 + c12
y = s1 + s12
```


Cost: 4 multiplications, 4 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn tip_pose(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::Isometry2<f64> {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let cos_phi = c1 * c2 - s1 * s2;
        let sin_phi = s1 * c2 + c1 * s2;
        let x = c1 + cos_phi;
        let y = s1 + sin_phi;
        ::planar_arm::__private::pose(x, y, cos_phi, sin_phi)
    }
    /**The Jacobian d(x, y, phi)/dq.

```text
J11 = -s1 - s12
J12 = -s12
J21 = c1 + c12
J22 = c12
J31 = 1
J32 = 1
```


Cost: 4 multiplications, 6 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn jacobian(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::planar_arm::nalgebra::SMatrix<f64, 3, 2> {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let j22 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let j11 = -s1 - s12;
        let j12 = -s12;
        let j21 = c1 + j22;
        let j31 = 1.0;
        ::planar_arm::__private::matrix([[j11, j12], [j21, j22], [j31, j31]])
    }
    /**The position of each joint, joint 1 at the origin.

Cost: 0 multiplications, 0 additions, 0 divisions, 1 sin_cos calls.*/
    #[inline]
    fn joint_positions(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> [::planar_arm::nalgebra::Point2<f64>; 2] {
        let [q1, _] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let x1 = 0.0;
        [
            ::planar_arm::nalgebra::Point2::new(x1, x1),
            ::planar_arm::nalgebra::Point2::new(c1, s1),
        ]
    }
    /**The tip in polar form: r from r^2 (which does not depend on q1), theta = atan2(y, x).

```text
r^2 = 2 + 2 c2
```


Cost: 5 multiplications, 5 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn tip_polar(&self, q: &::planar_arm::nalgebra::SVector<f64, 2>) -> (f64, f64) {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let r2 = 2.0 + 2.0 * c2;
        let c12 = c2 * c1 - s2 * s1;
        let s12 = c2 * s1 + s2 * c1;
        let x = c1 + c12;
        let y = s1 + s12;
        ::planar_arm::__private::polar(r2, x, y)
    }
    /**Statics: tau = J^T (u, v, torque), the motor torques that make the tip exert force (u, v) and torque `torque`.

Cost: 8 multiplications, 10 additions, 0 divisions, 2 sin_cos calls.*/
    #[inline]
    fn joint_torques(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
        force: &::planar_arm::nalgebra::Vector2<f64>,
        torque: f64,
    ) -> ::planar_arm::nalgebra::SVector<f64, 2> {
        let [q1, q2] = ::planar_arm::__private::unpack(q);
        let [u, v] = ::planar_arm::__private::unpack(force);
        let (s1, c1) = q1.sin_cos();
        let (s2, c2) = q2.sin_cos();
        let c12 = c1 * c2 - s1 * s2;
        let s12 = s1 * c2 + c1 * s2;
        let tau1 = torque + u * (-s1 - s12) + v * (c1 + c12);
        let tau2 = torque + u * (-s12) + v * c12;
        ::planar_arm::__private::vector([tau1, tau2])
    }
}
#[automatically_derived]
impl ::planar_arm::kinematics::ClosedFormIk<2> for Paper2 {
    type Target = ::planar_arm::nalgebra::Point2<f64>;
    ///The paper's closed form for two equal links: cos(q2/2) = r / 2l, q1 + q2/2 = atan2(y, x).
    #[inline]
    fn inverse_kinematics(
        &self,
        target: &::planar_arm::nalgebra::Point2<f64>,
    ) -> ::core::result::Result<
        [::planar_arm::nalgebra::SVector<f64, 2>; 2],
        ::planar_arm::ArmError,
    > {
        ::planar_arm::kinematics::ik2_equal(1.0, target)
    }
}
#[automatically_derived]
impl ::planar_arm::kinematics::TipForce for Paper2 {
    #[inline]
    fn tip_force(
        &self,
        q: &::planar_arm::nalgebra::SVector<f64, 2>,
        tau: &::planar_arm::nalgebra::SVector<f64, 2>,
    ) -> ::core::result::Result<
        ::planar_arm::nalgebra::Vector2<f64>,
        ::planar_arm::ArmError,
    > {
        ::planar_arm::kinematics::tip_force2(1.0, 1.0, q, tau)
    }
}
