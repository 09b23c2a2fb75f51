#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::Dynamics<6> for Puma560 {
    /**The gravity torques g = dV/dq (forces for slides) that hold the arm.

```text
g1 = 0
g2 = 372347379/10000000 c2 + 199143/800000 c23 - 256041/250000 s2 - 87439473/10000000 s23 + 8829/1250000 sin(q2 + q3 - q4 - q5) - 8829/1250000 sin(q2 + q3 - q4 + q5) - 8829/625000 sin(q2 + q3 - q5) - 8829/625000 sin(q2 + q3 + q5) + 8829/1250000 sin(q2 + q3 + q4 - q5) - 8829/1250000 s2345
g3 = 199143/800000 c23 - 87439473/10000000 s23 + 8829/1250000 sin(q2 + q3 - q4 - q5) - 8829/1250000 sin(q2 + q3 - q4 + q5) - 8829/625000 sin(q2 + q3 - q5) - 8829/625000 sin(q2 + q3 + q5) + 8829/1250000 sin(q2 + q3 + q4 - q5) - 8829/1250000 s2345
g4 = -8829/1250000 sin(q2 + q3 - q4 - q5) + 8829/1250000 sin(q2 + q3 - q4 + q5) + 8829/1250000 sin(q2 + q3 + q4 - q5) - 8829/1250000 s2345
g5 = -8829/1250000 sin(q2 + q3 - q4 - q5) - 8829/1250000 sin(q2 + q3 - q4 + q5) + 8829/625000 sin(q2 + q3 - q5) - 8829/625000 sin(q2 + q3 + q5) - 8829/1250000 sin(q2 + q3 + q4 - q5) - 8829/1250000 s2345
g6 = 0
```


Cost: 24 multiplications, 36 additions, 0 divisions, 4 sin_cos pairs.*/
    #[inline]
    fn gravity<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 6> {
        let [_, __q2, __q3, __q4, __q5, _] = ::planar_arm::__private::unpack(__q);
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
        ]);
        let __c23 = __c2 * __c3 - __s2 * __s3;
        let __s23 = __s2 * __c3 + __c2 * __s3;
        let __t1 = __T::from_f64(199143.0 / 800000.0) * __c23;
        let __t2 = __T::from_f64(87439473.0 / 10000000.0) * __s23;
        let __t3 = __c23 * __c4;
        let __t4 = __s23 * __s4;
        let __t5 = __s23 * __c4;
        let __t6 = __c23 * __s4;
        let __c2p3m4 = __t3 + __t4;
        let __s2p3m4 = __t5 - __t6;
        let __t7 = __s2p3m4 * __c5;
        let __t8 = __c2p3m4 * __s5;
        let __s2p3m4m5 = __t7 - __t8;
        let __t9 = __T::from_f64(8829.0 / 1250000.0) * __s2p3m4m5;
        let __s2p3m4p5 = __t7 + __t8;
        let __t10 = __T::from_f64(8829.0 / 1250000.0) * __s2p3m4p5;
        let __t11 = __s23 * __c5;
        let __t12 = __c23 * __s5;
        let __s2p3m5 = __t11 - __t12;
        let __t13 = __T::from_f64(8829.0 / 625000.0) * __s2p3m5;
        let __s2p3p5 = __t11 + __t12;
        let __t14 = __T::from_f64(8829.0 / 625000.0) * __s2p3p5;
        let __c234 = __t3 - __t4;
        let __s234 = __t5 + __t6;
        let __t15 = __c5 * __s234;
        let __t16 = __s5 * __c234;
        let __s2p3p4m5 = __t15 - __t16;
        let __t17 = __T::from_f64(8829.0 / 1250000.0) * __s2p3p4m5;
        let __s2345 = __t15 + __t16;
        let __t18 = __T::from_f64(8829.0 / 1250000.0) * __s2345;
        let __g2 = __T::from_f64(372347379.0 / 10000000.0) * __c2 + __t1 + __t9 + __t17
            - (__t10 + __T::from_f64(256041.0 / 250000.0) * __s2 + __t2 + __t18 + __t13
                + __t14);
        let __g3 = __t17 + __t1 + __t9 - (__t13 + __t2 + __t10 + __t14 + __t18);
        let __g4 = __t10 + __t17 - (__t9 + __t18);
        let __g5 = __t13 - (__t14 + __t9 + __t10 + __t17 + __t18);
        let __g1 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__g1, __g2, __g3, __g4, __g5, __g1])
    }
    /**The potential energy, zero at the base origin.

```text
V = 256041/250000 c2 + 87439473/10000000 c23 - 8829/1250000 cos(q2 + q3 - q4 - q5) + 8829/1250000 cos(q2 + q3 - q4 + q5) + 8829/625000 cos(q2 + q3 - q5) + 8829/625000 cos(q2 + q3 + q5) - 8829/1250000 cos(q2 + q3 + q4 - q5) + 8829/1250000 c2345 + 372347379/10000000 s2 + 199143/800000 s23
```


the first moment of every link's mass, dotted with gravity

Cost: 22 multiplications, 18 additions, 0 divisions, 4 sin_cos pairs.*/
    #[inline]
    fn potential_energy<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> __T {
        let [_, __q2, __q3, __q4, __q5, _] = ::planar_arm::__private::unpack(__q);
        let [(__s2, __c2), (__s3, __c3), (_, __c4), (__s5, __c5)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
        ]);
        let __t1 = __T::from_f64(2159.0 / 5000.0) * __s2;
        let __t2 = __s2 * __c3 + __c2 * __s3;
        let __t3 = __s2 * (-__s3) + __c2 * __c3;
        let __t4 = __t1 + __T::from_f64(203.0 / 10000.0) * __t2;
        let __t5 = __t4 + __T::from_f64(2159.0 / 5000.0) * __t3;
        let __v = -(__T::from_f64(-(981.0 / 100.0))
            * (__T::from_f64(9.0 / 100.0)
                * (__t5
                    + __T::from_f64(4.0 / 125.0) * (__t2 * __c4 * (-__s5) + __t3 * __c5))
                + __T::from_f64(17.0 / 50.0) * __t5
                + __T::from_f64(41.0 / 50.0)
                    * (__t5 + __T::from_f64(19.0 / 1000.0) * __t3)
                + __T::from_f64(24.0 / 5.0)
                    * (__t4 + __T::from_f64(-(203.0 / 10000.0)) * __t2
                        + __T::from_f64(7.0 / 100.0) * __t3)
                + __T::from_f64(87.0 / 5.0)
                    * (__t1 + __T::from_f64(-(1819.0 / 5000.0)) * __s2
                        + __T::from_f64(3.0 / 500.0) * __c2)));
        __v
    }
    /**The joint forces tau = M qdd + c + g + f (torques for hinges, forces for slides), M holding each joint's armature and f = damping qd + frictionloss sign(qd).

the recursive Newton-Euler algorithm unrolled, each link in its own frame, the joints' constant transformations folded in

Cost: 212 multiplications, 172 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn inverse_dynamics<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 6> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [__qdd1, __qdd2, __qdd3, __qdd4, __qdd5, _] = ::planar_arm::__private::unpack(
            __qdd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s3;
        let __t2 = -__s4;
        let __t3 = -__s5;
        let __t4 = -__s6;
        let __t5 = __s2 * __qd1;
        let __t6 = __c2 * __qd1;
        let __t7 = __s2 * __qdd1 + __qd2 * __t6;
        let __t8 = __c2 * __qdd1 - __qd2 * __t5;
        let __t9 = __T::from_f64(2159.0 / 5000.0) * __qd2;
        let __t10 = -(__T::from_f64(2159.0 / 5000.0) * __t6);
        let __t11 = __t5 * __t9 - __T::from_f64(2159.0 / 5000.0) * __t8;
        let __t12 = __T::from_f64(981.0 / 100.0) * __s2 + __t6 * __t10 - __qd2 * __t9;
        let __t13 = __T::from_f64(981.0 / 100.0) * __c2
            + __T::from_f64(2159.0 / 5000.0) * __qdd2 - __t5 * __t10;
        let __t14 = __c3 * __t5 + __s3 * __t6;
        let __t15 = __t1 * __t5 + __c3 * __t6;
        let __t16 = -__qd3;
        let __t17 = -__qd2 - __qd3;
        let __t18 = -__qdd2 - __qdd3;
        let __t19 = __c3 * __t7 + __s3 * __t8 - __t15 * __t16;
        let __t20 = __t1 * __t7 + __c3 * __t8 + __t14 * __t16;
        let __t21 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t15);
        let __t22 = __T::from_f64(203.0 / 10000.0) * __t15;
        let __t23 = __T::from_f64(-(3001.0 / 20000.0)) * __t14
            - __T::from_f64(203.0 / 10000.0) * __t17;
        let __t24 = __c3 * __t12 + __s3 * __t13 + __t17 * __t23 - __t15 * __t22
            - __T::from_f64(-(3001.0 / 20000.0)) * __t20;
        let __t25 = __t15 * __t21 - __t14 * __t23
            + __T::from_f64(203.0 / 10000.0) * __t20 - __t11;
        let __t26 = __t1 * __t12 + __c3 * __t13 + __t14 * __t22 - __t17 * __t21
            + __T::from_f64(-(3001.0 / 20000.0)) * __t19
            - __T::from_f64(203.0 / 10000.0) * __t18;
        let __t27 = __c4 * __t14 + __s4 * __t17;
        let __t28 = __t2 * __t14 + __c4 * __t17;
        let __t29 = -__t28;
        let __t30 = __t15 + __qd4;
        let __t31 = __c4 * __t19 + __s4 * __t18 - __qd4 * __t29;
        let __t32 = __qd4 * __t27 - (__t2 * __t19 + __c4 * __t18);
        let __t33 = -(__T::from_f64(2159.0 / 5000.0) * __t29);
        let __t34 = __T::from_f64(2159.0 / 5000.0) * __t27;
        let __t35 = __c4 * __t24 + __s4 * __t25 + __t30 * __t34
            - __T::from_f64(2159.0 / 5000.0) * __t32;
        let __t36 = __t26 + __t29 * __t33 - __t27 * __t34;
        let __t37 = __T::from_f64(2159.0 / 5000.0) * __t31 - __t30 * __t33
            - (__t2 * __t24 + __c4 * __t25);
        let __t38 = __c5 * __t35 + __s5 * __t36;
        let __t39 = __t3 * __t35 + __c5 * __t36;
        let __t40 = -__t37;
        let __t41 = __c5 * __t27 + __s5 * __t30;
        let __t42 = __t3 * __t27 + __c5 * __t30;
        let __t43 = __t28 - __qd5;
        let __t44 = -__t32 - __qdd5;
        let __t45 = __c5 * __t31 + __s5 * (__t20 + __qdd4) - __t42 * (-__qd5);
        let __t46 = __c6 * __t41 + __s6 * __t43;
        let __t47 = __t4 * __t41 + __c6 * __t43;
        let __t48 = __t42 + __qd6;
        let __t49 = __T::from_f64(91.0 / 400.0) * __t6
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t50 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t5;
        let __t51 = __T::from_f64(3.0 / 500.0) * __t5
            - __T::from_f64(-(1819.0 / 5000.0)) * __t6;
        let __t52 = __T::from_f64(87.0 / 5.0)
            * (__t12 + __t6 * __t51 - __qd2 * __t50 + __T::from_f64(91.0 / 400.0) * __t8
                - __T::from_f64(3.0 / 500.0) * __qdd2);
        let __t53 = __T::from_f64(87.0 / 5.0)
            * (__t13 + __qd2 * __t49 - __t5 * __t51
                + __T::from_f64(-(1819.0 / 5000.0)) * __qdd2
                - __T::from_f64(91.0 / 400.0) * __t7);
        let __t54 = __T::from_f64(87.0 / 5.0)
            * (__t11 + __t5 * __t50 - __t6 * __t49 + __T::from_f64(3.0 / 500.0) * __t7
                - __T::from_f64(-(1819.0 / 5000.0)) * __t8);
        let __t55 = __T::from_f64(7.0 / 100.0) * __t17
            - __T::from_f64(-(141.0 / 10000.0)) * __t15;
        let __t56 = __T::from_f64(-(203.0 / 10000.0)) * __t15
            - __T::from_f64(7.0 / 100.0) * __t14;
        let __t57 = __T::from_f64(-(141.0 / 10000.0)) * __t14
            - __T::from_f64(-(203.0 / 10000.0)) * __t17;
        let __t58 = __T::from_f64(24.0 / 5.0)
            * (__t24 + __t17 * __t57 - __t15 * __t56 + __T::from_f64(7.0 / 100.0) * __t18
                - __T::from_f64(-(141.0 / 10000.0)) * __t20);
        let __t59 = __T::from_f64(24.0 / 5.0)
            * (__t25 + __t15 * __t55 - __t14 * __t57
                + __T::from_f64(-(203.0 / 10000.0)) * __t20
                - __T::from_f64(7.0 / 100.0) * __t19);
        let __t60 = __T::from_f64(24.0 / 5.0)
            * (__t26 + __t14 * __t56 - __t17 * __t55
                + __T::from_f64(-(141.0 / 10000.0)) * __t19
                - __T::from_f64(-(203.0 / 10000.0)) * __t18);
        let __t61 = -(__T::from_f64(19.0 / 1000.0) * __t29);
        let __t62 = __T::from_f64(19.0 / 1000.0) * __t27;
        let __t63 = __T::from_f64(41.0 / 50.0)
            * (__t35 + __t30 * __t62 - __T::from_f64(19.0 / 1000.0) * __t32);
        let __t64 = __T::from_f64(41.0 / 50.0)
            * (__t37 + __T::from_f64(19.0 / 1000.0) * __t31 - __t30 * __t61);
        let __t65 = __T::from_f64(4.0 / 125.0) * __t47;
        let __t66 = -(__T::from_f64(4.0 / 125.0) * __t46);
        let __t67 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t38 + __s6 * __t40
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t45 + __c6 * __t44 - __qd6 * __t46) - __t48 * __t66);
        let __t68 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t38 + __c6 * __t40 + __t48 * __t65
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t45 + __s6 * __t44 + __qd6 * __t47));
        let __t69 = -(__T::from_f64(4.0 / 125.0) * __t68);
        let __t70 = __T::from_f64(4.0 / 125.0) * __t67;
        let __t71 = __c6 * __t69 + __t4 * __t70;
        let __t72 = __s6 * __t69 + __c6 * __t70;
        let __t73 = __T::from_f64(17.0 / 50.0) * __t38 + __c6 * __t67 + __t4 * __t68;
        let __t74 = __T::from_f64(17.0 / 50.0) * __t39
            + __T::from_f64(9.0 / 100.0) * (__t39 + __t46 * __t66 - __t47 * __t65);
        let __t5_2 = -__t72;
        let __t4_2 = __s5 * __t71;
        let __t75 = __t63 + __c5 * __t73 + __t3 * __t74;
        let __t76 = __t64
            - (__T::from_f64(17.0 / 50.0) * __t40 + __s6 * __t67 + __c6 * __t68);
        let __t77 = __T::from_f64(19.0 / 1000.0) * __t64 + __c5 * __t71
            + __T::from_f64(2159.0 / 5000.0) * __t76;
        let __t78 = -__t76;
        let __t79 = -(-(__T::from_f64(19.0 / 1000.0) * __t63) - __t72
            - __T::from_f64(2159.0 / 5000.0) * __t75);
        let __t80 = __t58 + __c4 * __t75 + __t2 * __t78;
        let __t81 = __t59 + __s4 * __t75 + __c4 * __t78;
        let __t82 = __t60
            + __T::from_f64(41.0 / 50.0) * (__t36 + __t29 * __t61 - __t27 * __t62)
            + __s5 * __t73 + __c5 * __t74;
        let __t83 = __T::from_f64(-(141.0 / 10000.0)) * __t60
            - __T::from_f64(7.0 / 100.0) * __t59 + __c4 * __t77 + __t2 * __t79
            + __T::from_f64(-(3001.0 / 20000.0)) * __t82;
        let __t84 = __T::from_f64(7.0 / 100.0) * __t58
            - __T::from_f64(-(203.0 / 10000.0)) * __t60 + __s4 * __t77 + __c4 * __t79
            - __T::from_f64(203.0 / 10000.0) * __t82;
        let __t85 = __T::from_f64(-(203.0 / 10000.0)) * __t59
            - __T::from_f64(-(141.0 / 10000.0)) * __t58 + __t4_2
            + __T::from_f64(203.0 / 10000.0) * __t81
            - __T::from_f64(-(3001.0 / 20000.0)) * __t80;
        let __t3_2 = -__t84;
        let __t2_2 = __T::from_f64(-(1819.0 / 5000.0)) * __t53
            - __T::from_f64(3.0 / 500.0) * __t52 - __t84
            + __T::from_f64(2159.0 / 5000.0) * (__t53 + __s3 * __t80 + __c3 * __t82);
        let __t1_2 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t54 - __T::from_f64(91.0 / 400.0) * __t53
                + __c3 * __t83 + __t1 * __t85)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t52
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t54 + __s3 * __t83
                    + __c3 * __t85 - __T::from_f64(2159.0 / 5000.0) * (__t54 - __t81));
        let __t6_2 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__t1_2, __t2_2, __t3_2, __t4_2, __t5_2, __t6_2])
    }
    /**The mass matrix M(q), each joint's armature on its diagonal.

Not multiplied out for this arm: a link's velocities would exceed 80 terms, and the products that M and c need would cost its build more than they are worth (`EXACT` has its tool pose, V and g where those fit). `#[arm(exact_dynamics)]` on the struct multiplies them out for `EXACT` and these docs whatever their size, as does `planar_arm::symbolic::spatial::lagrangian::expand_dynamics` (feature `symbolic`) for any budget.

the composite-rigid-body algorithm unrolled, each link in its own frame, the joints' constant transformations folded in

Cost: 155 multiplications, 166 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn mass_matrix<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 6, 6> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s3;
        let __t2 = -__s4;
        let __t3 = -__s6;
        let __t4 = __T::from_f64(36.0 / 390625.0) * __c6;
        let __t5 = __T::from_f64(36.0 / 390625.0) * __s6;
        let __t6 = __c6 * __t4;
        let __t7 = __t6 + __t3 * __T::from_f64(36.0 / 390625.0) * __t3;
        let __m55 = __t6 + __s6 * __t5;
        let __t8 = __T::from_f64(9.0 / 3125.0) * (-__s5);
        let __t9 = -(__c6 * __t5 + __t3 * __t4);
        let __t10 = __s5 * __t7;
        let __t11 = __c5 * __t10;
        let __m44 = __s5 * __t10;
        let __t12 = __c5 * __t9;
        let __m45 = __s5 * __t9;
        let __t13 = __T::from_f64(779.0 / 50000.0) + __T::from_f64(9.0 / 3125.0) * __c5;
        let __t14 = __T::from_f64(14801.0 / 50000000.0) + __c5 * __c5 * __t7;
        let __t15 = __c4 * __t8;
        let __t16 = __s4 * __t8;
        let __t17 = -__t12;
        let __t18 = __s4 * __t14 + __c4 * __t17;
        let __t19 = -__m45;
        let __t20 = __t2 * __t19;
        let __t21 = __c4 * __t19;
        let __t22 = -(__m55 + __T::from_f64(14801.0 / 50000000.0));
        let __t23 = __c4 * __t12;
        let __t24 = __s4 * __t12;
        let __t25 = -(__t24 + __c4 * __t22);
        let __t26 = __T::from_f64(2159.0 / 5000.0) * __t13;
        let __t27 = __T::from_f64(2.0) * __t26;
        let __t28 = __T::from_f64(4661281.0 / 20000000.0) + __t27;
        let __t29 = __T::from_f64(-(609.0 / 6250.0)) + __t15;
        let __t30 = __T::from_f64(-(423.0 / 6250.0)) + __t16;
        let __t31 = __T::from_f64(42.0 / 125.0) + __t13 + __T::from_f64(2159.0 / 4000.0);
        let __t32 = __T::from_f64(1529643.0 / 62500000.0)
            + __c4 * (__c4 * __t14 + __t2 * __t17) + __t2 * (-(__t23 + __t2 * __t22))
            + __t28;
        let __t33 = __T::from_f64(-(85869.0 / 62500000.0)) + __c4 * __t18 + __t2 * __t25;
        let __t34 = __T::from_f64(4263.0 / 625000.0) + __c4 * __t11 + __t20
            - __T::from_f64(2159.0 / 5000.0) * __t15;
        let __t35 = __T::from_f64(1593627.0 / 62500000.0) + __s4 * __t18 + __c4 * __t25
            + __t28;
        let __t36 = __T::from_f64(18327.0 / 6250000.0) + __m44 + __t27
            + __T::from_f64(4661281.0 / 20000000.0)
            + __T::from_f64(-(4661281.0 / 20000000.0)) - __t26 - __t26;
        let __t37 = __T::from_f64(203.0 / 10000.0) * __c3;
        let __t38 = __T::from_f64(203.0 / 10000.0) * __s3;
        let __t39 = -__t30;
        let __t40 = __c3 * __t29 + __t1 * __t31;
        let __t41 = __s3 * __t29 + __c3 * __t31;
        let __t42 = __T::from_f64(121.0 / 20.0) * __t37;
        let __t43 = __T::from_f64(121.0 / 20.0) * __t38;
        let __t44 = -__t33;
        let __t45 = __c3 * __t34;
        let __t46 = __s3 * __t32 + __t45;
        let __t47 = -(__T::from_f64(2961.0 / 625000.0) + __s4 * __t11 + __t21
            - __T::from_f64(2159.0 / 5000.0) * __t16);
        let __t48 = __s3 * __t34 + __c3 * __t36;
        let __t49 = __t37 * __t42;
        let __t50 = __t37 * __t40;
        let __t51 = __t38 * __t43;
        let __t52 = __T::from_f64(1089726121.0 / 8000000000.0) + __t49 + __t51;
        let __t53 = __t38 * __t41;
        let __t54 = __T::from_f64(3001.0 / 20000.0) * __t39;
        let __t55 = __T::from_f64(2.0) * (__t54 + __t50 + __t53);
        let __t56 = __T::from_f64(-(158253.0 / 25000.0)) + __t40 + __t42;
        let __t57 = __T::from_f64(261.0 / 2500.0) + __t41 + __t43;
        let __t58 = __T::from_f64(474759.0 / 12500000.0) + __c3 * __t46 + __t1 * __t48
            + -(__t38 * __t42) - __t37 * __t41 - __t38 * __t40;
        let __t59 = __T::from_f64(2159.0 / 5000.0) * __c2;
        let __t60 = __T::from_f64(2159.0 / 5000.0) * __s2;
        let __t61 = __t60 * __T::from_f64(469.0 / 20.0) * __t60;
        let __t62 = __t60 * (__s2 * __t56 + __c2 * __t57);
        let __m11 = __s2
            * (__s2
                * (__T::from_f64(18023703.0 / 20000000.0)
                    + __c3 * (__c3 * __t32 + __t1 * __t34)
                    + __t1 * (__t45 + __t1 * __t36) + __t55 + -__t49 - __t50 - __t50
                    + __t52) + __c2 * __t58)
            + __c2
                * (__s2 * __t58
                    + __c2
                        * (__T::from_f64(1601728203.0 / 500000000.0) + __s3 * __t46
                            + __c3 * __t48 + __t55 + __t52 + -__t51 - __t53 - __t53))
            + __T::from_f64(2.0) * (__t59 * (__c2 * __t56 + (-__s2) * __t57) + __t62)
            + __t59 * __T::from_f64(469.0 / 20.0) * __t59 + __t61 + -__t61 - __t62
            - __t62;
        let __m22 = __T::from_f64(287940507.0 / 125000000.0) + __t35 + __t55 + __t52
            + __T::from_f64(-(1089726121.0 / 8000000000.0)) - __t54 - __t54
            + __T::from_f64(2159.0 / 5000.0) * __t56
            + __T::from_f64(2159.0 / 5000.0)
                * (__t56 + __T::from_f64(1012571.0 / 100000.0));
        let __m12 = __c2
            * (__T::from_f64(-(23751.0 / 1000000.0)) + __s3 * __t44 + __c3 * __t47
                + -(__T::from_f64(3001.0 / 20000.0) * __t43) - __t38 * __t39
                - __T::from_f64(3001.0 / 20000.0) * __t41)
            + __s2
                * (__T::from_f64(14401023.0 / 10000000.0) + __c3 * __t44 + __t1 * __t47
                    + -(__T::from_f64(3001.0 / 20000.0) * __t42) - __t37 * __t39
                    - __T::from_f64(3001.0 / 20000.0) * __t40
                    - __T::from_f64(2159.0 / 5000.0)
                        * (__T::from_f64(7917.0 / 2000.0)
                            + __T::from_f64(363121.0 / 400000.0) - __t30));
        let __t63 = -__t31;
        let __t64 = __t29 + __T::from_f64(24563.0 / 200000.0);
        let __t65 = __T::from_f64(203.0 / 10000.0) * __t30 - __t33
            + __T::from_f64(-(3001.0 / 20000.0)) * __t64;
        let __t66 = -__t35 - __T::from_f64(203.0 / 10000.0) * __t29
            - __T::from_f64(203.0 / 10000.0) * __t64;
        let __t67 = __t47 - __T::from_f64(-(3001.0 / 20000.0)) * __t63;
        let __m33 = -__t66;
        let __m23 = __T::from_f64(2159.0 / 5000.0) * (__s3 * __t63 + __c3 * __t64)
            - __t66;
        let __m13 = __s2 * (__c3 * __t65 + __t1 * __t67)
            + __c2 * (__s3 * __t65 + __c3 * __t67);
        let __t68 = __t11 + __T::from_f64(2159.0 / 5000.0) * (-__t8);
        let __t69 = __t2 * __t8;
        let __t70 = __t20 + __c4 * __t68;
        let __t71 = __t21 + __s4 * __t68;
        let __t72 = __m44 + __T::from_f64(203.0 / 10000.0) * __t15
            - __T::from_f64(-(3001.0 / 20000.0)) * __t69;
        let __m34 = -__t71;
        let __m24 = __T::from_f64(2159.0 / 5000.0) * __s3 * __t69 - __t71;
        let __m14 = __s2 * (__c3 * __t70 + __t1 * __t72)
            + __c2
                * (__s3 * __t70 + __c3 * __t72
                    - __T::from_f64(2159.0 / 5000.0) * (-__t15));
        let __t73 = __T::from_f64(-(9.0 / 3125.0)) * __c5;
        let __t74 = __T::from_f64(-(9.0 / 3125.0)) * __s5;
        let __t75 = __c4 * __t73;
        let __t76 = __s4 * __t73;
        let __t77 = -(__m55 - __T::from_f64(2159.0 / 5000.0) * __t73);
        let __t78 = __t23 + __t2 * __t77 + __T::from_f64(-(3001.0 / 20000.0)) * __t74;
        let __t79 = __t24 + __c4 * __t77 - __T::from_f64(203.0 / 10000.0) * __t74;
        let __t80 = __m45 + __T::from_f64(203.0 / 10000.0) * __t76
            - __T::from_f64(-(3001.0 / 20000.0)) * __t75;
        let __m35 = -__t79;
        let __m25 = __T::from_f64(2159.0 / 5000.0) * (__s3 * __t75 + __c3 * __t74)
            - __t79;
        let __m15 = __s2 * (__c3 * __t78 + __t1 * __t80)
            + __c2
                * (__s3 * __t78 + __c3 * __t80
                    - __T::from_f64(2159.0 / 5000.0) * (-__t76));
        let __m16 = __T::from_f64(0.0);
        ::planar_arm::__private::columns([
            [__m11, __m12, __m13, __m14, __m15, __m16],
            [__m12, __m22, __m23, __m24, __m25, __m16],
            [__m13, __m23, __m33, __m34, __m35, __m16],
            [__m14, __m24, __m34, __m44, __m45, __m16],
            [__m15, __m25, __m35, __m45, __m55, __m16],
            [__m16, __m16, __m16, __m16, __m16, __m16],
        ])
    }
    /**The velocity-product (Coriolis and centrifugal) forces c(q, qd).

Not multiplied out for this arm: a link's velocities would exceed 80 terms, and the products that M and c need would cost its build more than they are worth (`EXACT` has its tool pose, V and g where those fit). `#[arm(exact_dynamics)]` on the struct multiplies them out for `EXACT` and these docs whatever their size, as does `planar_arm::symbolic::spatial::lagrangian::expand_dynamics` (feature `symbolic`) for any budget.

the recursive Newton-Euler algorithm unrolled, each link in its own frame, the joints' constant transformations folded in

Cost: 200 multiplications, 158 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn coriolis<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 6> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s3;
        let __t2 = -__s4;
        let __t3 = -__s5;
        let __t4 = -__s6;
        let __t5 = __s2 * __qd1;
        let __t6 = __c2 * __qd1;
        let __t7 = __qd2 * __t6;
        let __t8 = -(__qd2 * __t5);
        let __t9 = __T::from_f64(2159.0 / 5000.0) * __qd2;
        let __t10 = -(__T::from_f64(2159.0 / 5000.0) * __t6);
        let __t11 = __t6 * __t10 - __qd2 * __t9;
        let __t12 = __t5 * __t10;
        let __t13 = -__t12;
        let __t14 = __t5 * __t9 - __T::from_f64(2159.0 / 5000.0) * __t8;
        let __t15 = __c3 * __t5 + __s3 * __t6;
        let __t16 = __t1 * __t5 + __c3 * __t6;
        let __t17 = -__qd3;
        let __t18 = -__qd2 - __qd3;
        let __t19 = __c3 * __t7 + __s3 * __t8 - __t16 * __t17;
        let __t20 = __t1 * __t7 + __c3 * __t8 + __t15 * __t17;
        let __t21 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t16);
        let __t22 = __T::from_f64(203.0 / 10000.0) * __t16;
        let __t23 = __T::from_f64(-(3001.0 / 20000.0)) * __t15
            - __T::from_f64(203.0 / 10000.0) * __t18;
        let __t24 = __c3 * __t11 + __s3 * __t13 + __t18 * __t23 - __t16 * __t22
            - __T::from_f64(-(3001.0 / 20000.0)) * __t20;
        let __t25 = __t16 * __t21 - __t15 * __t23
            + __T::from_f64(203.0 / 10000.0) * __t20 - __t14;
        let __t26 = __t1 * __t11 + __c3 * __t13 + __t15 * __t22 - __t18 * __t21
            + __T::from_f64(-(3001.0 / 20000.0)) * __t19;
        let __t27 = __c4 * __t15 + __s4 * __t18;
        let __t28 = __t2 * __t15 + __c4 * __t18;
        let __t29 = -__t28;
        let __t30 = __t16 + __qd4;
        let __t31 = __c4 * __t19 - __qd4 * __t29;
        let __t32 = __qd4 * __t27 - __t2 * __t19;
        let __t33 = -(__T::from_f64(2159.0 / 5000.0) * __t29);
        let __t34 = __T::from_f64(2159.0 / 5000.0) * __t27;
        let __t35 = __c4 * __t24 + __s4 * __t25 + __t30 * __t34
            - __T::from_f64(2159.0 / 5000.0) * __t32;
        let __t36 = __t26 + __t29 * __t33 - __t27 * __t34;
        let __t37 = __T::from_f64(2159.0 / 5000.0) * __t31 - __t30 * __t33
            - (__t2 * __t24 + __c4 * __t25);
        let __t38 = __c5 * __t35 + __s5 * __t36;
        let __t39 = __t3 * __t35 + __c5 * __t36;
        let __t40 = -__t37;
        let __t41 = __c5 * __t27 + __s5 * __t30;
        let __t42 = __t3 * __t27 + __c5 * __t30;
        let __t43 = -__t32;
        let __t44 = __t28 - __qd5;
        let __t45 = __c5 * __t31 + __s5 * __t20 - __t42 * (-__qd5);
        let __t46 = __c6 * __t41 + __s6 * __t44;
        let __t47 = __t4 * __t41 + __c6 * __t44;
        let __t48 = __t42 + __qd6;
        let __t49 = __T::from_f64(91.0 / 400.0) * __t6
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t50 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t5;
        let __t51 = __T::from_f64(3.0 / 500.0) * __t5
            - __T::from_f64(-(1819.0 / 5000.0)) * __t6;
        let __t52 = __T::from_f64(87.0 / 5.0)
            * (__t11 + __t6 * __t51 - __qd2 * __t50
                + __T::from_f64(91.0 / 400.0) * __t8);
        let __t53 = __T::from_f64(87.0 / 5.0)
            * (__qd2 * __t49 - __t5 * __t51 - __T::from_f64(91.0 / 400.0) * __t7
                - __t12);
        let __t54 = __T::from_f64(87.0 / 5.0)
            * (__t14 + __t5 * __t50 - __t6 * __t49 + __T::from_f64(3.0 / 500.0) * __t7
                - __T::from_f64(-(1819.0 / 5000.0)) * __t8);
        let __t55 = __T::from_f64(7.0 / 100.0) * __t18
            - __T::from_f64(-(141.0 / 10000.0)) * __t16;
        let __t56 = __T::from_f64(-(203.0 / 10000.0)) * __t16
            - __T::from_f64(7.0 / 100.0) * __t15;
        let __t57 = __T::from_f64(-(141.0 / 10000.0)) * __t15
            - __T::from_f64(-(203.0 / 10000.0)) * __t18;
        let __t58 = __T::from_f64(24.0 / 5.0)
            * (__t24 + __t18 * __t57 - __t16 * __t56
                - __T::from_f64(-(141.0 / 10000.0)) * __t20);
        let __t59 = __T::from_f64(24.0 / 5.0)
            * (__t25 + __t16 * __t55 - __t15 * __t57
                + __T::from_f64(-(203.0 / 10000.0)) * __t20
                - __T::from_f64(7.0 / 100.0) * __t19);
        let __t60 = __T::from_f64(24.0 / 5.0)
            * (__t26 + __t15 * __t56 - __t18 * __t55
                + __T::from_f64(-(141.0 / 10000.0)) * __t19);
        let __t61 = -(__T::from_f64(19.0 / 1000.0) * __t29);
        let __t62 = __T::from_f64(19.0 / 1000.0) * __t27;
        let __t63 = __T::from_f64(41.0 / 50.0)
            * (__t35 + __t30 * __t62 - __T::from_f64(19.0 / 1000.0) * __t32);
        let __t64 = __T::from_f64(41.0 / 50.0)
            * (__t37 + __T::from_f64(19.0 / 1000.0) * __t31 - __t30 * __t61);
        let __t65 = __T::from_f64(4.0 / 125.0) * __t47;
        let __t66 = -(__T::from_f64(4.0 / 125.0) * __t46);
        let __t67 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t38 + __s6 * __t40
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t45 + __c6 * __t43 - __qd6 * __t46) - __t48 * __t66);
        let __t68 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t38 + __c6 * __t40 + __t48 * __t65
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t45 + __s6 * __t43 + __qd6 * __t47));
        let __t69 = -(__T::from_f64(4.0 / 125.0) * __t68);
        let __t70 = __T::from_f64(4.0 / 125.0) * __t67;
        let __t71 = __c6 * __t69 + __t4 * __t70;
        let __t72 = __s6 * __t69 + __c6 * __t70;
        let __t73 = __T::from_f64(17.0 / 50.0) * __t38 + __c6 * __t67 + __t4 * __t68;
        let __t74 = __T::from_f64(17.0 / 50.0) * __t39
            + __T::from_f64(9.0 / 100.0) * (__t39 + __t46 * __t66 - __t47 * __t65);
        let __t5_2 = -__t72;
        let __t4_2 = __s5 * __t71;
        let __t75 = __t63 + __c5 * __t73 + __t3 * __t74;
        let __t76 = __t64
            - (__T::from_f64(17.0 / 50.0) * __t40 + __s6 * __t67 + __c6 * __t68);
        let __t77 = __T::from_f64(19.0 / 1000.0) * __t64 + __c5 * __t71
            + __T::from_f64(2159.0 / 5000.0) * __t76;
        let __t78 = -__t76;
        let __t79 = -(-(__T::from_f64(19.0 / 1000.0) * __t63) - __t72
            - __T::from_f64(2159.0 / 5000.0) * __t75);
        let __t80 = __t58 + __c4 * __t75 + __t2 * __t78;
        let __t81 = __t59 + __s4 * __t75 + __c4 * __t78;
        let __t82 = __t60
            + __T::from_f64(41.0 / 50.0) * (__t36 + __t29 * __t61 - __t27 * __t62)
            + __s5 * __t73 + __c5 * __t74;
        let __t83 = __T::from_f64(-(141.0 / 10000.0)) * __t60
            - __T::from_f64(7.0 / 100.0) * __t59 + __c4 * __t77 + __t2 * __t79
            + __T::from_f64(-(3001.0 / 20000.0)) * __t82;
        let __t84 = __T::from_f64(7.0 / 100.0) * __t58
            - __T::from_f64(-(203.0 / 10000.0)) * __t60 + __s4 * __t77 + __c4 * __t79
            - __T::from_f64(203.0 / 10000.0) * __t82;
        let __t85 = __T::from_f64(-(203.0 / 10000.0)) * __t59
            - __T::from_f64(-(141.0 / 10000.0)) * __t58 + __t4_2
            + __T::from_f64(203.0 / 10000.0) * __t81
            - __T::from_f64(-(3001.0 / 20000.0)) * __t80;
        let __t3_2 = -__t84;
        let __t2_2 = __T::from_f64(-(1819.0 / 5000.0)) * __t53
            - __T::from_f64(3.0 / 500.0) * __t52 - __t84
            + __T::from_f64(2159.0 / 5000.0) * (__t53 + __s3 * __t80 + __c3 * __t82);
        let __t1_2 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t54 - __T::from_f64(91.0 / 400.0) * __t53
                + __c3 * __t83 + __t1 * __t85)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t52
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t54 + __s3 * __t83
                    + __c3 * __t85 - __T::from_f64(2159.0 / 5000.0) * (__t54 - __t81));
        let __t6_2 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__t1_2, __t2_2, __t3_2, __t4_2, __t5_2, __t6_2])
    }
    /**The Coriolis matrix C(q, qd) from Christoffel symbols: C qd = c, and Mdot - 2C is skew.

Christoffel symbols of the unrolled composite-rigid-body program's mass matrix, differentiated at compile time

Cost: 668 multiplications, 647 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn coriolis_matrix<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 6, 6> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s2;
        let __t2 = -__s3;
        let __t3 = -__s4;
        let __t4 = -__s5;
        let __t5 = -__s6;
        let __t6 = __T::from_f64(36.0 / 390625.0) * __c6;
        let __t7 = __T::from_f64(36.0 / 390625.0) * __s6;
        let __t8 = __T::from_f64(36.0 / 390625.0) * __t5;
        let __t9 = __c6 * __t6;
        let __t10 = __t5 * __t8;
        let __t11 = __t9 + __t10;
        let __t12 = __c6 * __t7;
        let __t13 = __t5 * __t6;
        let __t14 = __t9 + __s6 * __t7;
        let __t15 = __T::from_f64(9.0 / 3125.0) * __t4;
        let __t16 = -(__t12 + __t13);
        let __t17 = __c5 * __t11;
        let __t18 = __s5 * __t11;
        let __t19 = __c5 * __t17;
        let __t20 = __c5 * __t18;
        let __t21 = __s5 * __t18;
        let __t22 = __c5 * __t16;
        let __t23 = __s5 * __t16;
        let __t24 = __T::from_f64(779.0 / 50000.0) + __T::from_f64(9.0 / 3125.0) * __c5;
        let __t25 = __T::from_f64(14801.0 / 50000000.0) + __t19;
        let __t26 = __c4 * __t15;
        let __t27 = __s4 * __t15;
        let __t28 = -__t22;
        let __t29 = __t3 * __t28;
        let __t30 = __c4 * __t25 + __t29;
        let __t31 = __c4 * __t28;
        let __t32 = __s4 * __t25 + __t31;
        let __t33 = -__t23;
        let __t34 = __t3 * __t33;
        let __t35 = -(__t14 + __T::from_f64(14801.0 / 50000000.0));
        let __t36 = __c4 * __t22;
        let __t37 = -(__t36 + __t3 * __t35);
        let __t38 = __c4 * __t30;
        let __t39 = __t3 * __t37;
        let __t40 = -(__s4 * __t22 + __c4 * __t35);
        let __t41 = __c4 * __t32;
        let __t42 = __t3 * __t40;
        let __t43 = __T::from_f64(2159.0 / 5000.0) * __t24;
        let __t44 = __T::from_f64(2.0) * __t43;
        let __t45 = __c4 * __t20 + __t34 - __T::from_f64(2159.0 / 5000.0) * __t26;
        let __t46 = __T::from_f64(-(609.0 / 6250.0)) + __t26;
        let __t47 = __T::from_f64(-(423.0 / 6250.0)) + __t27;
        let __t48 = __T::from_f64(42.0 / 125.0) + __t24 + __T::from_f64(2159.0 / 4000.0);
        let __t49 = __T::from_f64(1529643.0 / 62500000.0) + __t38 + __t39
            + __T::from_f64(4661281.0 / 20000000.0) + __t44;
        let __t50 = __T::from_f64(-(85869.0 / 62500000.0)) + __t41 + __t42;
        let __t51 = __T::from_f64(4263.0 / 625000.0) + __t45;
        let __t52 = __T::from_f64(18327.0 / 6250000.0) + __t21 + __t44
            + __T::from_f64(4661281.0 / 20000000.0)
            + __T::from_f64(-(4661281.0 / 20000000.0)) - __t43 - __t43;
        let __t53 = __T::from_f64(203.0 / 10000.0) * __c3;
        let __t54 = __T::from_f64(203.0 / 10000.0) * __s3;
        let __t55 = -__t47;
        let __t56 = __c3 * __t46 + __t2 * __t48;
        let __t57 = __s3 * __t46 + __c3 * __t48;
        let __t58 = __T::from_f64(121.0 / 20.0) * __t53;
        let __t59 = __T::from_f64(121.0 / 20.0) * __t54;
        let __t60 = __t56 + __t58;
        let __t61 = -__t50;
        let __t62 = __t2 * __t51;
        let __t63 = __c3 * __t49 + __t62;
        let __t64 = __c3 * __t51;
        let __t65 = __s3 * __t49 + __t64;
        let __t66 = -(__T::from_f64(2961.0 / 625000.0) + __s4 * __t20 + __c4 * __t33
            - __T::from_f64(2159.0 / 5000.0) * __t27);
        let __t67 = __t64 + __t2 * __t52;
        let __t68 = __s3 * __t51 + __c3 * __t52;
        let __t69 = __c3 * __t63;
        let __t70 = __t2 * __t67;
        let __t71 = __c3 * __t65;
        let __t72 = __t2 * __t68;
        let __t73 = __t53 * __t58;
        let __t74 = __t53 * __t56;
        let __t75 = __t54 * __t59;
        let __t76 = __T::from_f64(1089726121.0 / 8000000000.0) + __t73 + __t75;
        let __t77 = __t54 * __t57;
        let __t78 = __T::from_f64(2.0)
            * (__T::from_f64(3001.0 / 20000.0) * __t55 + __t74 + __t77);
        let __t79 = __t54 * __t58;
        let __t80 = __t53 * __t57;
        let __t81 = __t54 * __t56;
        let __t82 = __c3 * __t61 + __t2 * __t66
            + -(__T::from_f64(3001.0 / 20000.0) * __t58) - __t53 * __t55
            - __T::from_f64(3001.0 / 20000.0) * __t56;
        let __t83 = __T::from_f64(-(158253.0 / 25000.0)) + __t60;
        let __t84 = __T::from_f64(261.0 / 2500.0) + __t57 + __t59;
        let __t85 = __T::from_f64(18023703.0 / 20000000.0) + __t69 + __t70 + __t78
            + -__t73 - __t74 - __t74 + __t76;
        let __t86 = __T::from_f64(474759.0 / 12500000.0) + __t71 + __t72 + -__t79 - __t80
            - __t81;
        let __t87 = __T::from_f64(1601728203.0 / 500000000.0) + __s3 * __t65
            + __c3 * __t68 + __t78 + __t76 + -__t75 - __t77 - __t77;
        let __t88 = __T::from_f64(2159.0 / 5000.0) * __c2;
        let __t89 = __T::from_f64(2159.0 / 5000.0) * __s2;
        let __t90 = __c2 * __t83 + __t1 * __t84;
        let __t91 = __T::from_f64(469.0 / 20.0) * __t88;
        let __t92 = __c2 * __t86;
        let __t93 = __t1
            * (__T::from_f64(-(23751.0 / 1000000.0)) + __s3 * __t61 + __c3 * __t66
                + -(__T::from_f64(3001.0 / 20000.0) * __t59) - __t54 * __t55
                - __T::from_f64(3001.0 / 20000.0) * __t57)
            + __c2
                * (__T::from_f64(14401023.0 / 10000000.0) + __t82
                    - __T::from_f64(2159.0 / 5000.0)
                        * (__T::from_f64(7917.0 / 2000.0)
                            + __T::from_f64(363121.0 / 400000.0) - __t47));
        let __t94 = -__t48;
        let __t95 = __t46 + __T::from_f64(24563.0 / 200000.0);
        let __t96 = __T::from_f64(203.0 / 10000.0) * __t47 - __t50
            + __T::from_f64(-(3001.0 / 20000.0)) * __t95;
        let __t97 = __t66 - __T::from_f64(-(3001.0 / 20000.0)) * __t94;
        let __t98 = __c2 * (__c3 * __t96 + __t2 * __t97);
        let __t99 = __t98 + __t1 * (__s3 * __t96 + __c3 * __t97);
        let __t100 = -__t15;
        let __t101 = __t20 + __T::from_f64(2159.0 / 5000.0) * __t100;
        let __t102 = __t3 * __t15;
        let __t103 = __t34 + __c4 * __t101;
        let __t104 = __T::from_f64(203.0 / 10000.0) * __t26;
        let __t105 = __T::from_f64(-(3001.0 / 20000.0)) * __t102;
        let __t106 = __t21 + __t104 - __t105;
        let __t107 = -__t26;
        let __t108 = __c3 * __t102;
        let __t109 = __s3 * __t102;
        let __t110 = __T::from_f64(2159.0 / 5000.0) * __t107;
        let __t111 = __c2 * (__c3 * __t103 + __t2 * __t106);
        let __t112 = __t111 + __t1 * (__s3 * __t103 + __c3 * __t106 - __t110);
        let __t113 = __T::from_f64(-(9.0 / 3125.0)) * __c5;
        let __t114 = __T::from_f64(-(9.0 / 3125.0)) * __s5;
        let __t115 = __c4 * __t113;
        let __t116 = __s4 * __t113;
        let __t117 = -(__t14 - __T::from_f64(2159.0 / 5000.0) * __t113);
        let __t118 = __t36 + __t3 * __t117;
        let __t119 = __t118 + __T::from_f64(-(3001.0 / 20000.0)) * __t114;
        let __t120 = __t23 + __T::from_f64(203.0 / 10000.0) * __t116
            - __T::from_f64(-(3001.0 / 20000.0)) * __t115;
        let __t121 = __c2 * (__c3 * __t119 + __t2 * __t120);
        let __t122 = __t121
            + __t1
                * (__s3 * __t119 + __c3 * __t120
                    - __T::from_f64(2159.0 / 5000.0) * (-__t116));
        let __t123 = -__c3;
        let __t124 = -__c4;
        let __t125 = -__c6;
        let __t126 = __c6 * __t8 + __t13;
        let __t127 = __t126 + __t8 * __t125
            + __t5 * __T::from_f64(36.0 / 390625.0) * __t125;
        let __t128 = __t126 + __s6 * __t6 + __t12;
        let __t129 = __T::from_f64(9.0 / 3125.0) * (-__c5);
        let __t130 = -(__t9 + __t5 * __t7 + __t10 + __t6 * __t125);
        let __t131 = __s5 * __t127;
        let __t132 = __t4 * __t17 + __c5 * __t4 * __t11;
        let __t133 = __c5 * __c5 * __t127;
        let __t134 = __t19 + __t4 * __t18;
        let __t135 = __c5 * __t131;
        let __t136 = __s5 * __t17 + __t20;
        let __t137 = __s5 * __t131;
        let __t138 = __t4 * __t16;
        let __t139 = __c5 * __t130;
        let __t140 = __s5 * __t130;
        let __t141 = __c4 * __t129;
        let __t142 = __s4 * __t129;
        let __t143 = -__t138;
        let __t144 = -__t139;
        let __t145 = __s4 * __t132 + __c4 * __t143;
        let __t146 = __s4 * __t133 + __c4 * __t144;
        let __t147 = -__t140;
        let __t148 = __t33 * __t124;
        let __t149 = __c4 * __t135 + __t3 * __t147;
        let __t150 = __s4 * __t135 + __c4 * __t147;
        let __t151 = -__t128;
        let __t152 = __t3 * __t22;
        let __t153 = __c4 * __t138;
        let __t154 = __c4 * __t139 + __t3 * __t151;
        let __t155 = __s4 * __t138;
        let __t156 = __s4 * __t139 + __c4 * __t151;
        let __t157 = __t3 * __t30 + __c4 * (__t3 * __t25 + __t28 * __t124)
            + __t37 * __t124 + __t3 * (-(__t152 + __t35 * __t124));
        let __t158 = __c4 * (__c4 * __t133 + __t3 * __t144) + __t3 * (-__t154);
        let __t159 = -__t155;
        let __t160 = -__t156;
        let __t161 = __t38 + __t3 * __t32 + __t39 + __t40 * __t124;
        let __t162 = __c4 * __t145 + __t3 * __t159;
        let __t163 = __s4 * __t30 + __t41 + __c4 * __t37 + __t42;
        let __t164 = __s4 * __t146 + __c4 * __t160;
        let __t165 = __T::from_f64(2159.0 / 5000.0) * __t15;
        let __t166 = __T::from_f64(2.0) * __t165;
        let __t167 = __c4 * (__c4 * __t132 + __t3 * __t143) + __t3 * (-__t153) + __t166;
        let __t168 = __t3 * __t20 + __t148 - __T::from_f64(2159.0 / 5000.0) * __t102;
        let __t169 = __t29 + __c4 * __t134 - __T::from_f64(2159.0 / 5000.0) * __t141;
        let __t170 = __s4 * __t145 + __c4 * __t159 + __t166;
        let __t171 = __t136 + __t166 + -__t165 - __t165;
        let __t172 = __T::from_f64(203.0 / 10000.0) * __t2;
        let __t173 = -__t142;
        let __t174 = __c3 * __t141;
        let __t175 = __t2 * __t46 + __t48 * __t123;
        let __t176 = __t174 + __t2 * __t15;
        let __t177 = __s3 * __t141 + __c3 * __t15;
        let __t178 = __T::from_f64(121.0 / 20.0) * __t172;
        let __t179 = __t175 + __t178;
        let __t180 = -__t161;
        let __t181 = -__t162;
        let __t182 = -(__c4 * __t146 + __t3 * __t160);
        let __t183 = __c3 * __t168;
        let __t184 = __c3 * __t169;
        let __t185 = __c3 * __t149;
        let __t186 = __s3 * __t157 + __t183;
        let __t187 = __s3 * __t167 + __t184;
        let __t188 = __s3 * __t158 + __t185;
        let __t189 = -__t164;
        let __t190 = -__t45;
        let __t191 = -(__t31 + __s4 * __t134 - __T::from_f64(2159.0 / 5000.0) * __t142);
        let __t192 = -__t150;
        let __t193 = __t185 + __t2 * __t137;
        let __t194 = __s3 * __t168;
        let __t195 = __s3 * __t169 + __c3 * __t171;
        let __t196 = __s3 * __t149 + __c3 * __t137;
        let __t197 = __c3 * __t188 + __t2 * __t196;
        let __t198 = __t2 * __t190;
        let __t199 = __c3 * __t190;
        let __t200 = __t58 * __t172 + __t53 * __t178;
        let __t201 = __t56 * __t172 + __t53 * __t175;
        let __t202 = __t53 * __t108;
        let __t203 = __t53 * __t176;
        let __t204 = __t79 + __t53 * __t59;
        let __t205 = __t200 + __t204;
        let __t206 = __t80 + __t81;
        let __t207 = __t54 * __t109;
        let __t208 = __t54 * __t177;
        let __t209 = __T::from_f64(3001.0 / 20000.0) * __t107;
        let __t210 = __T::from_f64(3001.0 / 20000.0) * __t173;
        let __t211 = __T::from_f64(2.0) * (__t201 + __t206);
        let __t212 = __T::from_f64(2.0) * (__t209 + __t202 + __t207);
        let __t213 = __T::from_f64(2.0) * (__t210 + __t203 + __t208);
        let __t214 = __t69 + __t2 * __t65 + __t70 + __t68 * __t123
            + -(__t73 + __t54 * __t178) - (__t74 + __t57 * __t172)
            - (__t74 + __t54 * __t175);
        let __t215 = __c3 * __t186 + __t2 * __t194 + -(__t53 * __t109) - __t54 * __t108;
        let __t216 = __c3 * __t187 + __t2 * __t195 + -(__t53 * __t177) - __t54 * __t176;
        let __t217 = __T::from_f64(2159.0 / 5000.0) * __t1;
        let __t218 = __s2
            * (__s2 * (__c3 * (__c3 * __t158 + __t2 * __t149) + __t2 * __t193)
                + __c2 * __t197)
            + __c2 * (__s2 * __t197 + __c2 * (__s3 * __t188 + __c3 * __t196));
        let __t219 = __t89 * __t91 + __t88 * __T::from_f64(469.0 / 20.0) * __t89;
        let __t220 = __t88 * (__s2 * __t83 + __c2 * __t84) + __t89 * __t90;
        let __t221 = __t89 * (__s2 * __t179 + __c2 * __t60);
        let __t222 = __t89 * (__s2 * __t108 + __c2 * __t109);
        let __t223 = __t89 * (__s2 * __t176 + __c2 * __t177);
        let __t224 = __s2 * (__c2 * __t85 + __t1 * __t86) + __c2 * (__s2 * __t85 + __t92)
            + __c2 * (__t92 + __t1 * __t87) + __t1 * (__s2 * __t86 + __c2 * __t87)
            + __T::from_f64(2.0)
                * (__t90 * __t217 + __t88 * (__t1 * __t83 + __t84 * (-__c2)) + __t220)
            + __t91 * __t217 + __t88 * __T::from_f64(469.0 / 20.0) * __t217 + __t219
            + -__t219 - __t220 - __t220;
        let __t225 = __s2
            * (__s2
                * (__t2 * __t63 + __c3 * (__t2 * __t49 + __t51 * __t123) + __t67 * __t123
                    + __t2 * (__t62 + __t52 * __t123) + __t211 + -__t200 - __t201
                    - __t201 + __t205) + __c2 * __t214)
            + __c2
                * (__s2 * __t214
                    + __c2
                        * (__s3 * __t63 + __t71 + __c3 * __t67 + __t72 + __t211 + __t205
                            + -__t204 - __t206 - __t206))
            + __T::from_f64(2.0) * (__t88 * (__c2 * __t179 + __t1 * __t60) + __t221)
            + -__t221 - __t221;
        let __t226 = __s2
            * (__s2
                * (__c3 * (__c3 * __t157 + __t2 * __t168) + __t2 * __t183 + -__t202
                    - __t202 + __t212) + __c2 * __t215)
            + __c2
                * (__s2 * __t215
                    + __c2 * (__s3 * __t186 + __c3 * __t194 + __t212 + -__t207 - __t207))
            + __T::from_f64(2.0) * (__t88 * (__c2 * __t108 + __t1 * __t109) + __t222)
            + -__t222 - __t222;
        let __t227 = __s2
            * (__s2
                * (__c3 * (__c3 * __t167 + __t2 * __t169)
                    + __t2 * (__t184 + __t2 * __t171) + -__t203 - __t203 + __t213)
                + __c2 * __t216)
            + __c2
                * (__s2 * __t216
                    + __c2 * (__s3 * __t187 + __c3 * __t195 + __t213 + -__t208 - __t208))
            + __T::from_f64(2.0) * (__t88 * (__c2 * __t176 + __t1 * __t177) + __t223)
            + -__t223 - __t223;
        let __t228 = __T::from_f64(2159.0 / 5000.0) * __t179;
        let __t229 = __T::from_f64(2159.0 / 5000.0) * __t108;
        let __t230 = __T::from_f64(2159.0 / 5000.0) * __t176;
        let __t231 = __t228 + __t205 + __t211 + __t228;
        let __t232 = __t229 + __t163 + __t212 + -__t209 - __t209 + __t229;
        let __t233 = __t230 + __t170 + __t213 + -__t210 - __t210 + __t230;
        let __t234 = __c2 * __t82
            + __s2
                * (__t2 * __t61 + __t66 * __t123
                    + -(__T::from_f64(3001.0 / 20000.0) * __t178) - __t55 * __t172
                    - __T::from_f64(3001.0 / 20000.0) * __t175);
        let __t235 = __c2
            * (__s3 * __t180 + __t199 + -(__t54 * __t107)
                - __T::from_f64(3001.0 / 20000.0) * __t109)
            + __s2
                * (__c3 * __t180 + __t198 + -(__t53 * __t107)
                    - __T::from_f64(3001.0 / 20000.0) * __t108 - __t110);
        let __t236 = __c2
            * (__s3 * __t181 + __c3 * __t191 + -(__t54 * __t173)
                - __T::from_f64(3001.0 / 20000.0) * __t177)
            + __s2
                * (__c3 * __t181 + __t2 * __t191 + -(__t53 * __t173)
                    - __T::from_f64(3001.0 / 20000.0) * __t176
                    - __T::from_f64(2159.0 / 5000.0) * __t173);
        let __t237 = __c2 * (__s3 * __t182 + __c3 * __t192)
            + __s2 * (__c3 * __t182 + __t2 * __t192);
        let __t238 = __T::from_f64(203.0 / 10000.0) * __t102;
        let __t239 = __T::from_f64(203.0 / 10000.0) * __t141;
        let __t240 = __t105 + __t104 - __t161;
        let __t241 = __T::from_f64(203.0 / 10000.0) * __t142 - __t162
            + __T::from_f64(-(3001.0 / 20000.0)) * __t141;
        let __t242 = -__t163 - __t238 - __t238;
        let __t243 = -__t170 - __t239 - __t239;
        let __t244 = __t191 - __T::from_f64(-(3001.0 / 20000.0)) * __t100;
        let __t245 = -__t242;
        let __t246 = -__t243;
        let __t247 = __T::from_f64(2159.0 / 5000.0) * (__c3 * __t94 + __t2 * __t95);
        let __t248 = __t229 - __t242;
        let __t249 = __T::from_f64(2159.0 / 5000.0) * (__t174 + __s3 * __t100) - __t243;
        let __t250 = __t98 + __s2 * (__t2 * __t96 + __t97 * __t123);
        let __t251 = __s2 * (__t198 + __c3 * __t240) + __c2 * (__t199 + __s3 * __t240);
        let __t252 = __s2 * (__c3 * __t241 + __t2 * __t244)
            + __c2 * (__s3 * __t241 + __c3 * __t244);
        let __t253 = __t134 + __T::from_f64(2159.0 / 5000.0) * (-__t129);
        let __t254 = __t15 * __t124;
        let __t255 = __t3 * __t129;
        let __t256 = __t148 + __t3 * __t101;
        let __t257 = __t29 + __c4 * __t253;
        let __t258 = __t31 + __s4 * __t253;
        let __t259 = __t238 - __T::from_f64(-(3001.0 / 20000.0)) * __t254;
        let __t260 = __t136 + __t239 - __T::from_f64(-(3001.0 / 20000.0)) * __t255;
        let __t261 = __T::from_f64(2159.0 / 5000.0) * __s3 * __t254 - __t103;
        let __t262 = __T::from_f64(2159.0 / 5000.0) * __s3 * __t255 - __t258;
        let __t263 = __t111 + __s2 * (__t2 * __t103 + __t106 * __t123);
        let __t264 = __s2 * (__c3 * __t256 + __t2 * __t259)
            + __c2
                * (__s3 * __t256 + __c3 * __t259
                    - __T::from_f64(2159.0 / 5000.0) * (-__t102));
        let __t265 = __s2 * (__c3 * __t257 + __t2 * __t260)
            + __c2
                * (__s3 * __t257 + __c3 * __t260
                    - __T::from_f64(2159.0 / 5000.0) * (-__t141));
        let __t266 = __s2 * __t193 + __c2 * __t196;
        let __t267 = __T::from_f64(-(9.0 / 3125.0)) * __t4;
        let __t268 = __T::from_f64(2159.0 / 5000.0) * __t267;
        let __t269 = __t3 * __t113;
        let __t270 = __c4 * __t267;
        let __t271 = __s4 * __t267;
        let __t272 = __t152 + __t117 * __t124;
        let __t273 = __T::from_f64(203.0 / 10000.0) * __t115
            - __T::from_f64(-(3001.0 / 20000.0)) * __t269;
        let __t274 = __t153 + __t3 * __t268
            + __T::from_f64(-(3001.0 / 20000.0)) * __t113;
        let __t275 = __t155 + __c4 * __t268 - __T::from_f64(203.0 / 10000.0) * __t113;
        let __t276 = __t22 + __T::from_f64(203.0 / 10000.0) * __t271
            - __T::from_f64(-(3001.0 / 20000.0)) * __t270;
        let __t277 = __T::from_f64(2159.0 / 5000.0) * (__c3 * __t115 + __t2 * __t114);
        let __t278 = __T::from_f64(2159.0 / 5000.0) * __s3 * __t269 - __t118;
        let __t279 = __T::from_f64(2159.0 / 5000.0) * (__s3 * __t270 + __c3 * __t113)
            - __t275;
        let __t280 = __t121 + __s2 * (__t2 * __t119 + __t120 * __t123);
        let __t281 = __s2 * (__c3 * __t272 + __t2 * __t273)
            + __c2
                * (__s3 * __t272 + __c3 * __t273
                    - __T::from_f64(2159.0 / 5000.0) * (-__t115));
        let __t282 = __s2 * (__c3 * __t274 + __t2 * __t276)
            + __c2
                * (__s3 * __t274 + __c3 * __t276
                    - __T::from_f64(2159.0 / 5000.0) * (-__t271));
        let __t283 = __s2 * (__c3 * __t154 + __t2 * __t140)
            + __c2 * (__s3 * __t154 + __c3 * __t140);
        let __c11 = __T::from_f64(1.0 / 2.0)
            * (__t218 * __qd6 + __t227 * __qd5 + __t226 * __qd4 + __t224 * __qd2
                + __t225 * __qd3);
        let __t284 = __t99 + __t234;
        let __t285 = __t112 + __t235;
        let __t286 = __t122 + __t236;
        let __t287 = __t237 * __qd6;
        let __c12 = __T::from_f64(1.0 / 2.0)
            * (__t287 + __qd5 * __t286 + __qd4 * __t285 + __qd3 * __t284 + __t224 * __qd1
                + __qd2 * (__t93 + __t93));
        let __t288 = __t251 + __t263;
        let __t289 = __t252 + __t280;
        let __c13 = __T::from_f64(1.0 / 2.0)
            * (__t287 + __qd5 * __t289 + __qd4 * __t288 + __qd3 * (__t250 + __t250)
                + __t225 * __qd1 + __qd2 * __t284);
        let __t290 = __t265 + __t281;
        let __t291 = __t266 * __qd6;
        let __c14 = __T::from_f64(1.0 / 2.0)
            * (__t291 + __qd5 * __t290 + __qd4 * (__t264 + __t264) + __qd3 * __t288
                + __t226 * __qd1 + __qd2 * __t285);
        let __t292 = __t283 * __qd6;
        let __c15 = __T::from_f64(1.0 / 2.0)
            * (__t292 + __qd5 * (__t282 + __t282) + __qd4 * __t290 + __qd3 * __t289
                + __t227 * __qd1 + __qd2 * __t286);
        let __c16 = __T::from_f64(1.0 / 2.0)
            * (__t283 * __qd5 + __t266 * __qd4 + __t237 * __qd3 + __t218 * __qd1
                + __t237 * __qd2);
        let __t293 = __t234 - __t99;
        let __t294 = __t235 - __t112;
        let __t295 = __t236 - __t122;
        let __c21 = __T::from_f64(1.0 / 2.0)
            * (__t287 + __qd5 * __t295 + __qd4 * __t294 + __qd1 * (-__t224)
                + __qd3 * __t293);
        let __t296 = __t164 * __qd6;
        let __c22 = __T::from_f64(1.0 / 2.0)
            * (__t296 + __t233 * __qd5 + __t231 * __qd3 + __t232 * __qd4);
        let __t297 = __t229 + __t248;
        let __t298 = __t249 + __t277;
        let __c23 = __T::from_f64(1.0 / 2.0)
            * (__t296 + __qd5 * __t298 + __qd4 * __t297 + __qd3 * (__t247 + __t247)
                + __qd1 * __t293 + __t231 * __qd2);
        let __t299 = __t262 + __t278;
        let __t300 = __t192 * __qd6;
        let __c24 = __T::from_f64(1.0 / 2.0)
            * (__t300 + __qd5 * __t299 + __qd4 * (__t261 + __t261) + __qd3 * __t297
                + __qd1 * __t294 + __t232 * __qd2);
        let __t301 = __t160 * __qd6;
        let __c25 = __T::from_f64(1.0 / 2.0)
            * (__t301 + __qd5 * (__t279 + __t279) + __qd4 * __t299 + __qd3 * __t298
                + __qd1 * __t295 + __t233 * __qd2);
        let __c26 = __T::from_f64(1.0 / 2.0)
            * (__t160 * __qd5 + __t192 * __qd4 + __t164 * __qd3 + __t237 * __qd1
                + __t164 * __qd2);
        let __t302 = __t99 - __t234;
        let __t303 = __t251 - __t263;
        let __t304 = __t252 - __t280;
        let __c31 = __T::from_f64(1.0 / 2.0)
            * (__t287 + __qd5 * __t304 + __qd4 * __t303 + __qd1 * (-__t225)
                + __qd2 * __t302);
        let __t305 = __t248 - __t229;
        let __t306 = __t249 - __t277;
        let __c32 = __T::from_f64(1.0 / 2.0)
            * (__t296 + __qd5 * __t306 + __qd4 * __t305 + __qd1 * __t302
                + __qd2 * (-__t231));
        let __c33 = __T::from_f64(1.0 / 2.0)
            * (__t296 + __t245 * __qd4 + __t246 * __qd5);
        let __c34 = __T::from_f64(1.0 / 2.0)
            * (__t300 + __qd5 * (-__t258 - __t118) + __qd4 * (-__t103 - __t103)
                + __t245 * __qd3 + __qd1 * __t303 + __qd2 * __t305);
        let __c35 = __T::from_f64(1.0 / 2.0)
            * (__t301 + __qd5 * (-__t275 - __t275) + __qd4 * (-__t118 - __t258)
                + __t246 * __qd3 + __qd1 * __t304 + __qd2 * __t306);
        let __t307 = __t112 - __t235;
        let __t308 = __t263 - __t251;
        let __t309 = __t265 - __t281;
        let __c41 = __T::from_f64(1.0 / 2.0)
            * (__t291 + __qd5 * __t309 + __qd3 * __t308 + __qd1 * (-__t226)
                + __qd2 * __t307);
        let __t310 = __t229 - __t248;
        let __t311 = __t262 - __t278;
        let __c42 = __T::from_f64(1.0 / 2.0)
            * (__t300 + __qd5 * __t311 + __qd3 * __t310 + __qd1 * __t307
                + __qd2 * (-__t232));
        let __t312 = __t118 - __t258;
        let __c43 = __T::from_f64(1.0 / 2.0)
            * (__t300 + __qd5 * __t312 + __t242 * __qd3 + __qd1 * __t308
                + __qd2 * __t310);
        let __c44 = __T::from_f64(1.0 / 2.0) * (__t136 * __qd5 + __t137 * __qd6);
        let __t313 = __t140 * __qd6;
        let __c45 = __T::from_f64(1.0 / 2.0)
            * (__t313 + __qd5 * (__t22 + __t22) + __t136 * __qd4 + __qd3 * __t312
                + __qd1 * __t309 + __qd2 * __t311);
        let __c46 = __T::from_f64(1.0 / 2.0)
            * (__t140 * __qd5 + __t137 * __qd4 + __t192 * __qd3 + __t266 * __qd1
                + __t192 * __qd2);
        let __t314 = __t122 - __t236;
        let __t315 = __t280 - __t252;
        let __t316 = __t281 - __t265;
        let __c51 = __T::from_f64(1.0 / 2.0)
            * (__t292 + __qd4 * __t316 + __qd3 * __t315 + __qd1 * (-__t227)
                + __qd2 * __t314);
        let __t317 = __t277 - __t249;
        let __t318 = __t278 - __t262;
        let __c52 = __T::from_f64(1.0 / 2.0)
            * (__t301 + __qd4 * __t318 + __qd3 * __t317 + __qd1 * __t314
                + __qd2 * (-__t233));
        let __t319 = __t258 - __t118;
        let __c53 = __T::from_f64(1.0 / 2.0)
            * (__t301 + __qd4 * __t319 + __t243 * __qd3 + __qd1 * __t315
                + __qd2 * __t317);
        let __c54 = __T::from_f64(1.0 / 2.0)
            * (__t313 + __qd4 * (-__t136) + __qd3 * __t319 + __qd1 * __t316
                + __qd2 * __t318);
        let __c55 = __T::from_f64(1.0 / 2.0) * __t128 * __qd6;
        let __c56 = __T::from_f64(1.0 / 2.0)
            * (__t128 * __qd5 + __t140 * __qd4 + __t160 * __qd3 + __t283 * __qd1
                + __t160 * __qd2);
        let __t320 = -__t237;
        let __t321 = -__t266;
        let __t322 = -__t283;
        let __c61 = __T::from_f64(1.0 / 2.0)
            * (__qd5 * __t322 + __qd4 * __t321 + __qd3 * __t320 + __qd1 * (-__t218)
                + __qd2 * __t320);
        let __c62 = __T::from_f64(1.0 / 2.0)
            * (__t156 * __qd5 + __t150 * __qd4 + __t189 * __qd3 + __qd1 * __t320
                + __t189 * __qd2);
        let __c64 = __T::from_f64(1.0 / 2.0)
            * (__t147 * __qd5 + __qd4 * (-__t137) + __t150 * __qd3 + __qd1 * __t321
                + __t150 * __qd2);
        let __c65 = __T::from_f64(1.0 / 2.0)
            * (__t151 * __qd5 + __t147 * __qd4 + __t156 * __qd3 + __qd1 * __t322
                + __t156 * __qd2);
        let __c66 = __T::from_f64(0.0);
        ::planar_arm::__private::columns([
            [__c11, __c21, __c31, __c41, __c51, __c61],
            [__c12, __c22, __c32, __c42, __c52, __c62],
            [__c13, __c23, __c33, __c43, __c53, __c62],
            [__c14, __c24, __c34, __c44, __c54, __c64],
            [__c15, __c25, __c35, __c45, __c55, __c65],
            [__c16, __c26, __c26, __c46, __c56, __c66],
        ])
    }
    /**The joint friction f = damping qd + frictionloss sign(qd), sign(0) = 0.

Cost: 0 multiplications, 0 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn friction<__T: ::planar_arm::Real>(
        &self,
        _: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 6> {
        let __f1 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__f1, __f1, __f1, __f1, __f1, __f1])
    }
    /**The bias h = c + g + f.

the recursive Newton-Euler algorithm unrolled, each link in its own frame, the joints' constant transformations folded in

Cost: 202 multiplications, 159 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn bias<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 6> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s3;
        let __t2 = -__s4;
        let __t3 = -__s5;
        let __t4 = -__s6;
        let __t5 = __s2 * __qd1;
        let __t6 = __c2 * __qd1;
        let __t7 = __qd2 * __t6;
        let __t8 = -(__qd2 * __t5);
        let __t9 = __T::from_f64(2159.0 / 5000.0) * __qd2;
        let __t10 = -(__T::from_f64(2159.0 / 5000.0) * __t6);
        let __t11 = __t5 * __t9 - __T::from_f64(2159.0 / 5000.0) * __t8;
        let __t12 = __T::from_f64(981.0 / 100.0) * __s2 + __t6 * __t10 - __qd2 * __t9;
        let __t13 = __T::from_f64(981.0 / 100.0) * __c2 - __t5 * __t10;
        let __t14 = __c3 * __t5 + __s3 * __t6;
        let __t15 = __t1 * __t5 + __c3 * __t6;
        let __t16 = -__qd3;
        let __t17 = -__qd2 - __qd3;
        let __t18 = __c3 * __t7 + __s3 * __t8 - __t15 * __t16;
        let __t19 = __t1 * __t7 + __c3 * __t8 + __t14 * __t16;
        let __t20 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t15);
        let __t21 = __T::from_f64(203.0 / 10000.0) * __t15;
        let __t22 = __T::from_f64(-(3001.0 / 20000.0)) * __t14
            - __T::from_f64(203.0 / 10000.0) * __t17;
        let __t23 = __c3 * __t12 + __s3 * __t13 + __t17 * __t22 - __t15 * __t21
            - __T::from_f64(-(3001.0 / 20000.0)) * __t19;
        let __t24 = __t15 * __t20 - __t14 * __t22
            + __T::from_f64(203.0 / 10000.0) * __t19 - __t11;
        let __t25 = __t1 * __t12 + __c3 * __t13 + __t14 * __t21 - __t17 * __t20
            + __T::from_f64(-(3001.0 / 20000.0)) * __t18;
        let __t26 = __c4 * __t14 + __s4 * __t17;
        let __t27 = __t2 * __t14 + __c4 * __t17;
        let __t28 = -__t27;
        let __t29 = __t15 + __qd4;
        let __t30 = __c4 * __t18 - __qd4 * __t28;
        let __t31 = __qd4 * __t26 - __t2 * __t18;
        let __t32 = -(__T::from_f64(2159.0 / 5000.0) * __t28);
        let __t33 = __T::from_f64(2159.0 / 5000.0) * __t26;
        let __t34 = __c4 * __t23 + __s4 * __t24 + __t29 * __t33
            - __T::from_f64(2159.0 / 5000.0) * __t31;
        let __t35 = __t25 + __t28 * __t32 - __t26 * __t33;
        let __t36 = __T::from_f64(2159.0 / 5000.0) * __t30 - __t29 * __t32
            - (__t2 * __t23 + __c4 * __t24);
        let __t37 = __c5 * __t34 + __s5 * __t35;
        let __t38 = __t3 * __t34 + __c5 * __t35;
        let __t39 = -__t36;
        let __t40 = __c5 * __t26 + __s5 * __t29;
        let __t41 = __t3 * __t26 + __c5 * __t29;
        let __t42 = -__t31;
        let __t43 = __t27 - __qd5;
        let __t44 = __c5 * __t30 + __s5 * __t19 - __t41 * (-__qd5);
        let __t45 = __c6 * __t40 + __s6 * __t43;
        let __t46 = __t4 * __t40 + __c6 * __t43;
        let __t47 = __t41 + __qd6;
        let __t48 = __T::from_f64(91.0 / 400.0) * __t6
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t49 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t5;
        let __t50 = __T::from_f64(3.0 / 500.0) * __t5
            - __T::from_f64(-(1819.0 / 5000.0)) * __t6;
        let __t51 = __T::from_f64(87.0 / 5.0)
            * (__t12 + __t6 * __t50 - __qd2 * __t49
                + __T::from_f64(91.0 / 400.0) * __t8);
        let __t52 = __T::from_f64(87.0 / 5.0)
            * (__t13 + __qd2 * __t48 - __t5 * __t50
                - __T::from_f64(91.0 / 400.0) * __t7);
        let __t53 = __T::from_f64(87.0 / 5.0)
            * (__t11 + __t5 * __t49 - __t6 * __t48 + __T::from_f64(3.0 / 500.0) * __t7
                - __T::from_f64(-(1819.0 / 5000.0)) * __t8);
        let __t54 = __T::from_f64(7.0 / 100.0) * __t17
            - __T::from_f64(-(141.0 / 10000.0)) * __t15;
        let __t55 = __T::from_f64(-(203.0 / 10000.0)) * __t15
            - __T::from_f64(7.0 / 100.0) * __t14;
        let __t56 = __T::from_f64(-(141.0 / 10000.0)) * __t14
            - __T::from_f64(-(203.0 / 10000.0)) * __t17;
        let __t57 = __T::from_f64(24.0 / 5.0)
            * (__t23 + __t17 * __t56 - __t15 * __t55
                - __T::from_f64(-(141.0 / 10000.0)) * __t19);
        let __t58 = __T::from_f64(24.0 / 5.0)
            * (__t24 + __t15 * __t54 - __t14 * __t56
                + __T::from_f64(-(203.0 / 10000.0)) * __t19
                - __T::from_f64(7.0 / 100.0) * __t18);
        let __t59 = __T::from_f64(24.0 / 5.0)
            * (__t25 + __t14 * __t55 - __t17 * __t54
                + __T::from_f64(-(141.0 / 10000.0)) * __t18);
        let __t60 = -(__T::from_f64(19.0 / 1000.0) * __t28);
        let __t61 = __T::from_f64(19.0 / 1000.0) * __t26;
        let __t62 = __T::from_f64(41.0 / 50.0)
            * (__t34 + __t29 * __t61 - __T::from_f64(19.0 / 1000.0) * __t31);
        let __t63 = __T::from_f64(41.0 / 50.0)
            * (__t36 + __T::from_f64(19.0 / 1000.0) * __t30 - __t29 * __t60);
        let __t64 = __T::from_f64(4.0 / 125.0) * __t46;
        let __t65 = -(__T::from_f64(4.0 / 125.0) * __t45);
        let __t66 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t37 + __s6 * __t39
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t44 + __c6 * __t42 - __qd6 * __t45) - __t47 * __t65);
        let __t67 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t37 + __c6 * __t39 + __t47 * __t64
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t44 + __s6 * __t42 + __qd6 * __t46));
        let __t68 = -(__T::from_f64(4.0 / 125.0) * __t67);
        let __t69 = __T::from_f64(4.0 / 125.0) * __t66;
        let __t70 = __c6 * __t68 + __t4 * __t69;
        let __t71 = __s6 * __t68 + __c6 * __t69;
        let __t72 = __T::from_f64(17.0 / 50.0) * __t37 + __c6 * __t66 + __t4 * __t67;
        let __t73 = __T::from_f64(17.0 / 50.0) * __t38
            + __T::from_f64(9.0 / 100.0) * (__t38 + __t45 * __t65 - __t46 * __t64);
        let __t5_2 = -__t71;
        let __t4_2 = __s5 * __t70;
        let __t74 = __t62 + __c5 * __t72 + __t3 * __t73;
        let __t75 = __t63
            - (__T::from_f64(17.0 / 50.0) * __t39 + __s6 * __t66 + __c6 * __t67);
        let __t76 = __T::from_f64(19.0 / 1000.0) * __t63 + __c5 * __t70
            + __T::from_f64(2159.0 / 5000.0) * __t75;
        let __t77 = -__t75;
        let __t78 = -(-(__T::from_f64(19.0 / 1000.0) * __t62) - __t71
            - __T::from_f64(2159.0 / 5000.0) * __t74);
        let __t79 = __t57 + __c4 * __t74 + __t2 * __t77;
        let __t80 = __t58 + __s4 * __t74 + __c4 * __t77;
        let __t81 = __t59
            + __T::from_f64(41.0 / 50.0) * (__t35 + __t28 * __t60 - __t26 * __t61)
            + __s5 * __t72 + __c5 * __t73;
        let __t82 = __T::from_f64(-(141.0 / 10000.0)) * __t59
            - __T::from_f64(7.0 / 100.0) * __t58 + __c4 * __t76 + __t2 * __t78
            + __T::from_f64(-(3001.0 / 20000.0)) * __t81;
        let __t83 = __T::from_f64(7.0 / 100.0) * __t57
            - __T::from_f64(-(203.0 / 10000.0)) * __t59 + __s4 * __t76 + __c4 * __t78
            - __T::from_f64(203.0 / 10000.0) * __t81;
        let __t84 = __T::from_f64(-(203.0 / 10000.0)) * __t58
            - __T::from_f64(-(141.0 / 10000.0)) * __t57 + __t4_2
            + __T::from_f64(203.0 / 10000.0) * __t80
            - __T::from_f64(-(3001.0 / 20000.0)) * __t79;
        let __t3_2 = -__t83;
        let __t2_2 = __T::from_f64(-(1819.0 / 5000.0)) * __t52
            - __T::from_f64(3.0 / 500.0) * __t51 - __t83
            + __T::from_f64(2159.0 / 5000.0) * (__t52 + __s3 * __t79 + __c3 * __t81);
        let __t1_2 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t53 - __T::from_f64(91.0 / 400.0) * __t52
                + __c3 * __t82 + __t1 * __t84)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t51
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t53 + __s3 * __t82
                    + __c3 * __t84 - __T::from_f64(2159.0 / 5000.0) * (__t53 - __t80));
        let __t6_2 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__t1_2, __t2_2, __t3_2, __t4_2, __t5_2, __t6_2])
    }
    /**The mass matrix and the bias h = c + g + f in one program.

the composite-rigid-body algorithm and the recursive Newton-Euler algorithm at zero acceleration, unrolled in one program, each link in its own frame

Cost: 357 multiplications, 321 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn mass_matrix_and_bias<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<__T, 6, 6>,
        ::planar_arm::nalgebra::SVector<__T, 6>,
    ) {
        self.__mass_matrix_and_bias_body(__q, __qd)
    }
    #[doc(hidden)]
    #[inline(always)]
    fn __mass_matrix_and_bias_body<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<__T, 6, 6>,
        ::planar_arm::nalgebra::SVector<__T, 6>,
    ) {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s3;
        let __t2 = -__s4;
        let __t3 = -__s5;
        let __t4 = -__s6;
        let __t5 = __T::from_f64(36.0 / 390625.0) * __c6;
        let __t6 = __T::from_f64(36.0 / 390625.0) * __s6;
        let __t7 = __c6 * __t5;
        let __t8 = __t7 + __t4 * __T::from_f64(36.0 / 390625.0) * __t4;
        let __m55 = __t7 + __s6 * __t6;
        let __t9 = __T::from_f64(9.0 / 3125.0) * __t3;
        let __t10 = -(__c6 * __t6 + __t4 * __t5);
        let __t11 = __s5 * __t8;
        let __t12 = __c5 * __t11;
        let __m44 = __s5 * __t11;
        let __t13 = __c5 * __t10;
        let __m45 = __s5 * __t10;
        let __t14 = __T::from_f64(779.0 / 50000.0) + __T::from_f64(9.0 / 3125.0) * __c5;
        let __t15 = __T::from_f64(14801.0 / 50000000.0) + __c5 * __c5 * __t8;
        let __t16 = __c4 * __t9;
        let __t17 = __s4 * __t9;
        let __t18 = -__t13;
        let __t19 = __s4 * __t15 + __c4 * __t18;
        let __t20 = -__m45;
        let __t21 = __t2 * __t20;
        let __t22 = __c4 * __t20;
        let __t23 = -(__m55 + __T::from_f64(14801.0 / 50000000.0));
        let __t24 = __c4 * __t13;
        let __t25 = __s4 * __t13;
        let __t26 = -(__t25 + __c4 * __t23);
        let __t27 = __T::from_f64(2159.0 / 5000.0) * __t14;
        let __t28 = __T::from_f64(2.0) * __t27;
        let __t29 = __T::from_f64(4661281.0 / 20000000.0) + __t28;
        let __t30 = __T::from_f64(-(609.0 / 6250.0)) + __t16;
        let __t31 = __T::from_f64(-(423.0 / 6250.0)) + __t17;
        let __t32 = __T::from_f64(42.0 / 125.0) + __t14 + __T::from_f64(2159.0 / 4000.0);
        let __t33 = __T::from_f64(1529643.0 / 62500000.0)
            + __c4 * (__c4 * __t15 + __t2 * __t18) + __t2 * (-(__t24 + __t2 * __t23))
            + __t29;
        let __t34 = __T::from_f64(-(85869.0 / 62500000.0)) + __c4 * __t19 + __t2 * __t26;
        let __t35 = __T::from_f64(4263.0 / 625000.0) + __c4 * __t12 + __t21
            - __T::from_f64(2159.0 / 5000.0) * __t16;
        let __t36 = __T::from_f64(1593627.0 / 62500000.0) + __s4 * __t19 + __c4 * __t26
            + __t29;
        let __t37 = __T::from_f64(18327.0 / 6250000.0) + __m44 + __t28
            + __T::from_f64(4661281.0 / 20000000.0)
            + __T::from_f64(-(4661281.0 / 20000000.0)) - __t27 - __t27;
        let __t38 = __T::from_f64(203.0 / 10000.0) * __c3;
        let __t39 = __T::from_f64(203.0 / 10000.0) * __s3;
        let __t40 = -__t31;
        let __t41 = __c3 * __t30 + __t1 * __t32;
        let __t42 = __s3 * __t30 + __c3 * __t32;
        let __t43 = __T::from_f64(121.0 / 20.0) * __t38;
        let __t44 = __T::from_f64(121.0 / 20.0) * __t39;
        let __t45 = -__t34;
        let __t46 = __c3 * __t35;
        let __t47 = __s3 * __t33 + __t46;
        let __t48 = -(__T::from_f64(2961.0 / 625000.0) + __s4 * __t12 + __t22
            - __T::from_f64(2159.0 / 5000.0) * __t17);
        let __t49 = __s3 * __t35 + __c3 * __t37;
        let __t50 = __t38 * __t43;
        let __t51 = __t38 * __t41;
        let __t52 = __t39 * __t44;
        let __t53 = __T::from_f64(1089726121.0 / 8000000000.0) + __t50 + __t52;
        let __t54 = __t39 * __t42;
        let __t55 = __T::from_f64(3001.0 / 20000.0) * __t40;
        let __t56 = __T::from_f64(2.0) * (__t55 + __t51 + __t54);
        let __t57 = __T::from_f64(-(158253.0 / 25000.0)) + __t41 + __t43;
        let __t58 = __T::from_f64(261.0 / 2500.0) + __t42 + __t44;
        let __t59 = __T::from_f64(474759.0 / 12500000.0) + __c3 * __t47 + __t1 * __t49
            + -(__t39 * __t43) - __t38 * __t42 - __t39 * __t41;
        let __t60 = __T::from_f64(2159.0 / 5000.0) * __c2;
        let __t61 = __T::from_f64(2159.0 / 5000.0) * __s2;
        let __t62 = __t61 * __T::from_f64(469.0 / 20.0) * __t61;
        let __t63 = __t61 * (__s2 * __t57 + __c2 * __t58);
        let __m11 = __s2
            * (__s2
                * (__T::from_f64(18023703.0 / 20000000.0)
                    + __c3 * (__c3 * __t33 + __t1 * __t35)
                    + __t1 * (__t46 + __t1 * __t37) + __t56 + -__t50 - __t51 - __t51
                    + __t53) + __c2 * __t59)
            + __c2
                * (__s2 * __t59
                    + __c2
                        * (__T::from_f64(1601728203.0 / 500000000.0) + __s3 * __t47
                            + __c3 * __t49 + __t56 + __t53 + -__t52 - __t54 - __t54))
            + __T::from_f64(2.0) * (__t60 * (__c2 * __t57 + (-__s2) * __t58) + __t63)
            + __t60 * __T::from_f64(469.0 / 20.0) * __t60 + __t62 + -__t62 - __t63
            - __t63;
        let __m22 = __T::from_f64(287940507.0 / 125000000.0) + __t36 + __t56 + __t53
            + __T::from_f64(-(1089726121.0 / 8000000000.0)) - __t55 - __t55
            + __T::from_f64(2159.0 / 5000.0) * __t57
            + __T::from_f64(2159.0 / 5000.0)
                * (__t57 + __T::from_f64(1012571.0 / 100000.0));
        let __m12 = __c2
            * (__T::from_f64(-(23751.0 / 1000000.0)) + __s3 * __t45 + __c3 * __t48
                + -(__T::from_f64(3001.0 / 20000.0) * __t44) - __t39 * __t40
                - __T::from_f64(3001.0 / 20000.0) * __t42)
            + __s2
                * (__T::from_f64(14401023.0 / 10000000.0) + __c3 * __t45 + __t1 * __t48
                    + -(__T::from_f64(3001.0 / 20000.0) * __t43) - __t38 * __t40
                    - __T::from_f64(3001.0 / 20000.0) * __t41
                    - __T::from_f64(2159.0 / 5000.0)
                        * (__T::from_f64(7917.0 / 2000.0)
                            + __T::from_f64(363121.0 / 400000.0) - __t31));
        let __t64 = -__t32;
        let __t65 = __t30 + __T::from_f64(24563.0 / 200000.0);
        let __t66 = __T::from_f64(203.0 / 10000.0) * __t31 - __t34
            + __T::from_f64(-(3001.0 / 20000.0)) * __t65;
        let __t67 = -__t36 - __T::from_f64(203.0 / 10000.0) * __t30
            - __T::from_f64(203.0 / 10000.0) * __t65;
        let __t68 = __t48 - __T::from_f64(-(3001.0 / 20000.0)) * __t64;
        let __m33 = -__t67;
        let __m23 = __T::from_f64(2159.0 / 5000.0) * (__s3 * __t64 + __c3 * __t65)
            - __t67;
        let __m13 = __s2 * (__c3 * __t66 + __t1 * __t68)
            + __c2 * (__s3 * __t66 + __c3 * __t68);
        let __t69 = __t12 + __T::from_f64(2159.0 / 5000.0) * (-__t9);
        let __t70 = __t2 * __t9;
        let __t71 = __t21 + __c4 * __t69;
        let __t72 = __t22 + __s4 * __t69;
        let __t73 = __m44 + __T::from_f64(203.0 / 10000.0) * __t16
            - __T::from_f64(-(3001.0 / 20000.0)) * __t70;
        let __m34 = -__t72;
        let __m24 = __T::from_f64(2159.0 / 5000.0) * __s3 * __t70 - __t72;
        let __m14 = __s2 * (__c3 * __t71 + __t1 * __t73)
            + __c2
                * (__s3 * __t71 + __c3 * __t73
                    - __T::from_f64(2159.0 / 5000.0) * (-__t16));
        let __t74 = __T::from_f64(-(9.0 / 3125.0)) * __c5;
        let __t75 = __T::from_f64(-(9.0 / 3125.0)) * __s5;
        let __t76 = __c4 * __t74;
        let __t77 = __s4 * __t74;
        let __t78 = -(__m55 - __T::from_f64(2159.0 / 5000.0) * __t74);
        let __t79 = __t24 + __t2 * __t78 + __T::from_f64(-(3001.0 / 20000.0)) * __t75;
        let __t80 = __t25 + __c4 * __t78 - __T::from_f64(203.0 / 10000.0) * __t75;
        let __t81 = __m45 + __T::from_f64(203.0 / 10000.0) * __t77
            - __T::from_f64(-(3001.0 / 20000.0)) * __t76;
        let __m35 = -__t80;
        let __m25 = __T::from_f64(2159.0 / 5000.0) * (__s3 * __t76 + __c3 * __t75)
            - __t80;
        let __m15 = __s2 * (__c3 * __t79 + __t1 * __t81)
            + __c2
                * (__s3 * __t79 + __c3 * __t81
                    - __T::from_f64(2159.0 / 5000.0) * (-__t77));
        let __t82 = __s2 * __qd1;
        let __t83 = __c2 * __qd1;
        let __t84 = __qd2 * __t83;
        let __t85 = -(__qd2 * __t82);
        let __t86 = __T::from_f64(2159.0 / 5000.0) * __qd2;
        let __t87 = -(__T::from_f64(2159.0 / 5000.0) * __t83);
        let __t88 = __t82 * __t86 - __T::from_f64(2159.0 / 5000.0) * __t85;
        let __t89 = __T::from_f64(981.0 / 100.0) * __s2 + __t83 * __t87 - __qd2 * __t86;
        let __t90 = __T::from_f64(981.0 / 100.0) * __c2 - __t82 * __t87;
        let __t91 = __c3 * __t82 + __s3 * __t83;
        let __t92 = __t1 * __t82 + __c3 * __t83;
        let __t93 = -__qd3;
        let __t94 = -__qd2 - __qd3;
        let __t95 = __c3 * __t84 + __s3 * __t85 - __t92 * __t93;
        let __t96 = __t1 * __t84 + __c3 * __t85 + __t91 * __t93;
        let __t97 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t92);
        let __t98 = __T::from_f64(203.0 / 10000.0) * __t92;
        let __t99 = __T::from_f64(-(3001.0 / 20000.0)) * __t91
            - __T::from_f64(203.0 / 10000.0) * __t94;
        let __t100 = __c3 * __t89 + __s3 * __t90 + __t94 * __t99 - __t92 * __t98
            - __T::from_f64(-(3001.0 / 20000.0)) * __t96;
        let __t101 = __t92 * __t97 - __t91 * __t99
            + __T::from_f64(203.0 / 10000.0) * __t96 - __t88;
        let __t102 = __t1 * __t89 + __c3 * __t90 + __t91 * __t98 - __t94 * __t97
            + __T::from_f64(-(3001.0 / 20000.0)) * __t95;
        let __t103 = __c4 * __t91 + __s4 * __t94;
        let __t104 = __t2 * __t91 + __c4 * __t94;
        let __t105 = -__t104;
        let __t106 = __t92 + __qd4;
        let __t107 = __c4 * __t95 - __qd4 * __t105;
        let __t108 = __qd4 * __t103 - __t2 * __t95;
        let __t109 = -(__T::from_f64(2159.0 / 5000.0) * __t105);
        let __t110 = __T::from_f64(2159.0 / 5000.0) * __t103;
        let __t111 = __c4 * __t100 + __s4 * __t101 + __t106 * __t110
            - __T::from_f64(2159.0 / 5000.0) * __t108;
        let __t112 = __t102 + __t105 * __t109 - __t103 * __t110;
        let __t113 = __T::from_f64(2159.0 / 5000.0) * __t107 - __t106 * __t109
            - (__t2 * __t100 + __c4 * __t101);
        let __t114 = __c5 * __t111 + __s5 * __t112;
        let __t115 = __t3 * __t111 + __c5 * __t112;
        let __t116 = -__t113;
        let __t117 = __c5 * __t103 + __s5 * __t106;
        let __t118 = __t3 * __t103 + __c5 * __t106;
        let __t119 = -__t108;
        let __t120 = __t104 - __qd5;
        let __t121 = __c5 * __t107 + __s5 * __t96 - __t118 * (-__qd5);
        let __t122 = __c6 * __t117 + __s6 * __t120;
        let __t123 = __t4 * __t117 + __c6 * __t120;
        let __t124 = __t118 + __qd6;
        let __t125 = __T::from_f64(91.0 / 400.0) * __t83
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t126 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t82;
        let __t127 = __T::from_f64(3.0 / 500.0) * __t82
            - __T::from_f64(-(1819.0 / 5000.0)) * __t83;
        let __t128 = __T::from_f64(87.0 / 5.0)
            * (__t89 + __t83 * __t127 - __qd2 * __t126
                + __T::from_f64(91.0 / 400.0) * __t85);
        let __t129 = __T::from_f64(87.0 / 5.0)
            * (__t90 + __qd2 * __t125 - __t82 * __t127
                - __T::from_f64(91.0 / 400.0) * __t84);
        let __t130 = __T::from_f64(87.0 / 5.0)
            * (__t88 + __t82 * __t126 - __t83 * __t125
                + __T::from_f64(3.0 / 500.0) * __t84
                - __T::from_f64(-(1819.0 / 5000.0)) * __t85);
        let __t131 = __T::from_f64(7.0 / 100.0) * __t94
            - __T::from_f64(-(141.0 / 10000.0)) * __t92;
        let __t132 = __T::from_f64(-(203.0 / 10000.0)) * __t92
            - __T::from_f64(7.0 / 100.0) * __t91;
        let __t133 = __T::from_f64(-(141.0 / 10000.0)) * __t91
            - __T::from_f64(-(203.0 / 10000.0)) * __t94;
        let __t134 = __T::from_f64(24.0 / 5.0)
            * (__t100 + __t94 * __t133 - __t92 * __t132
                - __T::from_f64(-(141.0 / 10000.0)) * __t96);
        let __t135 = __T::from_f64(24.0 / 5.0)
            * (__t101 + __t92 * __t131 - __t91 * __t133
                + __T::from_f64(-(203.0 / 10000.0)) * __t96
                - __T::from_f64(7.0 / 100.0) * __t95);
        let __t136 = __T::from_f64(24.0 / 5.0)
            * (__t102 + __t91 * __t132 - __t94 * __t131
                + __T::from_f64(-(141.0 / 10000.0)) * __t95);
        let __t137 = -(__T::from_f64(19.0 / 1000.0) * __t105);
        let __t138 = __T::from_f64(19.0 / 1000.0) * __t103;
        let __t139 = __T::from_f64(41.0 / 50.0)
            * (__t111 + __t106 * __t138 - __T::from_f64(19.0 / 1000.0) * __t108);
        let __t140 = __T::from_f64(41.0 / 50.0)
            * (__t113 + __T::from_f64(19.0 / 1000.0) * __t107 - __t106 * __t137);
        let __t141 = __T::from_f64(4.0 / 125.0) * __t123;
        let __t142 = -(__T::from_f64(4.0 / 125.0) * __t122);
        let __t143 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t114 + __s6 * __t116
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t121 + __c6 * __t119 - __qd6 * __t122)
                - __t124 * __t142);
        let __t144 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t114 + __c6 * __t116 + __t124 * __t141
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t121 + __s6 * __t119 + __qd6 * __t123));
        let __t145 = -(__T::from_f64(4.0 / 125.0) * __t144);
        let __t146 = __T::from_f64(4.0 / 125.0) * __t143;
        let __t147 = __c6 * __t145 + __t4 * __t146;
        let __t148 = __s6 * __t145 + __c6 * __t146;
        let __t149 = __T::from_f64(17.0 / 50.0) * __t114 + __c6 * __t143 + __t4 * __t144;
        let __t150 = __T::from_f64(17.0 / 50.0) * __t115
            + __T::from_f64(9.0 / 100.0) * (__t115 + __t122 * __t142 - __t123 * __t141);
        let __h5 = -__t148;
        let __h4 = __s5 * __t147;
        let __t151 = __t139 + __c5 * __t149 + __t3 * __t150;
        let __t152 = __t140
            - (__T::from_f64(17.0 / 50.0) * __t116 + __s6 * __t143 + __c6 * __t144);
        let __t153 = __T::from_f64(19.0 / 1000.0) * __t140 + __c5 * __t147
            + __T::from_f64(2159.0 / 5000.0) * __t152;
        let __t154 = -__t152;
        let __t155 = -(-(__T::from_f64(19.0 / 1000.0) * __t139) - __t148
            - __T::from_f64(2159.0 / 5000.0) * __t151);
        let __t156 = __t134 + __c4 * __t151 + __t2 * __t154;
        let __t157 = __t135 + __s4 * __t151 + __c4 * __t154;
        let __t158 = __t136
            + __T::from_f64(41.0 / 50.0) * (__t112 + __t105 * __t137 - __t103 * __t138)
            + __s5 * __t149 + __c5 * __t150;
        let __t159 = __T::from_f64(-(141.0 / 10000.0)) * __t136
            - __T::from_f64(7.0 / 100.0) * __t135 + __c4 * __t153 + __t2 * __t155
            + __T::from_f64(-(3001.0 / 20000.0)) * __t158;
        let __t160 = __T::from_f64(7.0 / 100.0) * __t134
            - __T::from_f64(-(203.0 / 10000.0)) * __t136 + __s4 * __t153 + __c4 * __t155
            - __T::from_f64(203.0 / 10000.0) * __t158;
        let __t161 = __T::from_f64(-(203.0 / 10000.0)) * __t135
            - __T::from_f64(-(141.0 / 10000.0)) * __t134 + __h4
            + __T::from_f64(203.0 / 10000.0) * __t157
            - __T::from_f64(-(3001.0 / 20000.0)) * __t156;
        let __h3 = -__t160;
        let __h2 = __T::from_f64(-(1819.0 / 5000.0)) * __t129
            - __T::from_f64(3.0 / 500.0) * __t128 - __t160
            + __T::from_f64(2159.0 / 5000.0) * (__t129 + __s3 * __t156 + __c3 * __t158);
        let __h1 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t130 - __T::from_f64(91.0 / 400.0) * __t129
                + __c3 * __t159 + __t1 * __t161)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t128
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t130 + __s3 * __t159
                    + __c3 * __t161
                    - __T::from_f64(2159.0 / 5000.0) * (__t130 - __t157));
        let __m16 = __T::from_f64(0.0);
        (
            ::planar_arm::__private::columns([
                [__m11, __m12, __m13, __m14, __m15, __m16],
                [__m12, __m22, __m23, __m24, __m25, __m16],
                [__m13, __m23, __m33, __m34, __m35, __m16],
                [__m14, __m24, __m34, __m44, __m45, __m16],
                [__m15, __m25, __m35, __m45, __m55, __m16],
                [__m16, __m16, __m16, __m16, __m16, __m16],
            ]),
            ::planar_arm::__private::vector([__h1, __h2, __h3, __h4, __h5, __m16]),
        )
    }
    /**The partial derivatives of `inverse_dynamics`, `(dtau/dq, dtau/dqd)` (`dtau/dqdd` is `mass_matrix`). Coulomb friction contributes 0 to `dtau/dqd`.

the unrolled recursive Newton-Euler algorithm differentiated at compile time, operation by operation, four directions at a time

Cost: 1456 multiplications, 1164 additions, 0 divisions, 5 sin_cos pairs; where the processor has AVX2 and FMA, 200 multiplications, 160 additions, 0 divisions, 5 sin_cos pairs on scalars and 799 four-lane operations (310 of them fused multiply-adds).*/
    #[inline]
    fn inverse_dynamics_derivatives(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
    ) {
        ::planar_arm::__private::dispatch(::planar_arm::__private::InverseDynamicsDerivatives::<
            Self,
            6,
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
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
    ) {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [__qdd1, __qdd2, __qdd3, __qdd4, __qdd5, _] = ::planar_arm::__private::unpack(
            __qdd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s2;
        let __t2 = -__s3;
        let __t3 = -__s4;
        let __t4 = -__s5;
        let __t5 = -__s6;
        let __t6 = (981.0 / 100.0) * __c2;
        let __t7 = __s2 * __qd1;
        let __t8 = __c2 * __qd1;
        let __t9 = __c2 * __qdd1;
        let __t10 = __qd2 * __t8;
        let __t11 = __s2 * __qdd1 + __t10;
        let __t12 = __t9 - __qd2 * __t7;
        let __t13 = (2159.0 / 5000.0) * __qd2;
        let __t14 = -((2159.0 / 5000.0) * __t8);
        let __t15 = __t8 * __t14;
        let __t16 = __t7 * __t13 - (2159.0 / 5000.0) * __t12;
        let __t17 = (981.0 / 100.0) * __s2 + __t15 - __qd2 * __t13;
        let __t18 = __t6 + (2159.0 / 5000.0) * __qdd2 - __t7 * __t14;
        let __t19 = __t2 * __t17 + __c3 * __t18;
        let __t20 = __c3 * __t7 + __s3 * __t8;
        let __t21 = __c3 * __t8;
        let __t22 = __t2 * __t7 + __t21;
        let __t23 = __t2 * __t11 + __c3 * __t12;
        let __t24 = -__qd3;
        let __t25 = -__qd2 - __qd3;
        let __t26 = __t22 * __t24;
        let __t27 = -__qdd2 - __qdd3;
        let __t28 = __c3 * __t11 + __s3 * __t12 - __t26;
        let __t29 = __t23 + __t20 * __t24;
        let __t30 = (-(3001.0 / 20000.0)) * __t22;
        let __t31 = -__t30;
        let __t32 = (203.0 / 10000.0) * __t22;
        let __t33 = (203.0 / 10000.0) * __t25;
        let __t34 = (-(3001.0 / 20000.0)) * __t20 - __t33;
        let __t35 = __t22 * __t32;
        let __t36 = __c3 * __t17 + __s3 * __t18 + __t25 * __t34 - __t35
            - (-(3001.0 / 20000.0)) * __t29;
        let __t37 = __t22 * __t31 - __t20 * __t34 + (203.0 / 10000.0) * __t29 - __t16;
        let __t38 = __t19 + __t20 * __t32 - __t25 * __t31 + (-(3001.0 / 20000.0)) * __t28
            - (203.0 / 10000.0) * __t27;
        let __t39 = __t3 * __t36 + __c4 * __t37;
        let __t40 = __c4 * __t20 + __s4 * __t25;
        let __t41 = __t3 * __t20 + __c4 * __t25;
        let __t42 = -__t41;
        let __t43 = __t3 * __t28 + __c4 * __t27;
        let __t44 = __t22 + __qd4;
        let __t45 = __t29 + __qdd4;
        let __t46 = __c4 * __t28 + __s4 * __t27 - __qd4 * __t42;
        let __t47 = __qd4 * __t40 - __t43;
        let __t48 = (2159.0 / 5000.0) * __t42;
        let __t49 = -__t48;
        let __t50 = (2159.0 / 5000.0) * __t40;
        let __t51 = __c4 * __t36 + __s4 * __t37 + __t44 * __t50
            - (2159.0 / 5000.0) * __t47;
        let __t52 = __t38 + __t42 * __t49 - __t40 * __t50;
        let __t53 = (2159.0 / 5000.0) * __t46 - __t44 * __t49 - __t39;
        let __t54 = __c5 * __t51 + __s5 * __t52;
        let __t55 = __t4 * __t51 + __c5 * __t52;
        let __t56 = -__t53;
        let __t57 = __c5 * __t40 + __s5 * __t44;
        let __t58 = __t4 * __t40 + __c5 * __t44;
        let __t59 = -__qd5;
        let __t60 = __t41 - __qd5;
        let __t61 = -__t47 - __qdd5;
        let __t62 = __c5 * __t46 + __s5 * __t45 - __t58 * __t59;
        let __t63 = __t5 * __t54 + __c6 * __t56;
        let __t64 = __c6 * __t57 + __s6 * __t60;
        let __t65 = __t5 * __t57 + __c6 * __t60;
        let __t66 = __t5 * __t62 + __c6 * __t61;
        let __t67 = __t58 + __qd6;
        let __t68 = __qd6 * __t65;
        let __t69 = (91.0 / 400.0) * __t8;
        let __t70 = __t69 - (3.0 / 500.0) * __qd2;
        let __t71 = (-(1819.0 / 5000.0)) * __qd2;
        let __t72 = __t71 - (91.0 / 400.0) * __t7;
        let __t73 = (3.0 / 500.0) * __t7 - (-(1819.0 / 5000.0)) * __t8;
        let __t74 = __t8 * __t73;
        let __t75 = (87.0 / 5.0)
            * (__t16 + __t7 * __t72 - __t8 * __t70 + (3.0 / 500.0) * __t11
                - (-(1819.0 / 5000.0)) * __t12);
        let __t76 = (-(141.0 / 10000.0)) * __t22;
        let __t77 = (7.0 / 100.0) * __t25 - __t76;
        let __t78 = (-(203.0 / 10000.0)) * __t22 - (7.0 / 100.0) * __t20;
        let __t79 = (-(203.0 / 10000.0)) * __t25;
        let __t80 = (-(141.0 / 10000.0)) * __t20 - __t79;
        let __t81 = __t22 * __t78;
        let __t82 = (24.0 / 5.0)
            * (__t36 + __t25 * __t80 - __t81 + (7.0 / 100.0) * __t27
                - (-(141.0 / 10000.0)) * __t29);
        let __t83 = (24.0 / 5.0)
            * (__t37 + __t22 * __t77 - __t20 * __t80 + (-(203.0 / 10000.0)) * __t29
                - (7.0 / 100.0) * __t28);
        let __t84 = (24.0 / 5.0)
            * (__t38 + __t20 * __t78 - __t25 * __t77 + (-(141.0 / 10000.0)) * __t28
                - (-(203.0 / 10000.0)) * __t27);
        let __t85 = (19.0 / 1000.0) * __t42;
        let __t86 = -__t85;
        let __t87 = (19.0 / 1000.0) * __t40;
        let __t88 = (41.0 / 50.0) * (__t51 + __t44 * __t87 - (19.0 / 1000.0) * __t47);
        let __t89 = (41.0 / 50.0) * (__t53 + (19.0 / 1000.0) * __t46 - __t44 * __t86);
        let __t90 = (17.0 / 50.0) * __t55;
        let __t91 = (4.0 / 125.0) * __t65;
        let __t92 = (4.0 / 125.0) * __t64;
        let __t93 = -__t92;
        let __t94 = (9.0 / 100.0)
            * (__c6 * __t54 + __s6 * __t56 + (4.0 / 125.0) * (__t66 - __qd6 * __t64)
                - __t67 * __t93);
        let __t95 = (9.0 / 100.0)
            * (__t63 + __t67 * __t91
                - (4.0 / 125.0) * (__c6 * __t62 + __s6 * __t61 + __t68));
        let __t96 = -((4.0 / 125.0) * __t95);
        let __t97 = (4.0 / 125.0) * __t94;
        let __t98 = __c6 * __t94;
        let __t99 = __t5 * __t95;
        let __t100 = __c6 * __t96;
        let __t101 = __t5 * __t97;
        let __t102 = __t100 + __t101;
        let __t103 = (17.0 / 50.0) * __t54 + __t98 + __t99;
        let __t104 = __t90 + (9.0 / 100.0) * (__t55 + __t64 * __t93 - __t65 * __t91);
        let __t105 = __c5 * __t103;
        let __t106 = __t4 * __t104;
        let __t107 = __c5 * __t102;
        let __t108 = __t88 + __t105 + __t106;
        let __t109 = __t89 - ((17.0 / 50.0) * __t56 + __s6 * __t94 + __c6 * __t95);
        let __t110 = (19.0 / 1000.0) * __t89 + __t107 + (2159.0 / 5000.0) * __t109;
        let __t111 = -__t109;
        let __t112 = __c4 * __t108;
        let __t113 = __t3 * __t111;
        let __t114 = -(-((19.0 / 1000.0) * __t88) - (__s6 * __t96 + __c6 * __t97)
            - (2159.0 / 5000.0) * __t108);
        let __t115 = __c4 * __t110;
        let __t116 = __t3 * __t114;
        let __t117 = __t82 + __t112 + __t113;
        let __t118 = __t83 + __s4 * __t108 + __c4 * __t111;
        let __t119 = __t84 + (41.0 / 50.0) * (__t52 + __t42 * __t86 - __t40 * __t87)
            + __s5 * __t103 + __c5 * __t104;
        let __t120 = (-(141.0 / 10000.0)) * __t84 - (7.0 / 100.0) * __t83 + __t115
            + __t116 + (-(3001.0 / 20000.0)) * __t119;
        let __t121 = (-(203.0 / 10000.0)) * __t83 - (-(141.0 / 10000.0)) * __t82
            + __s5 * __t102 + (203.0 / 10000.0) * __t118
            - (-(3001.0 / 20000.0)) * __t117;
        let __t122 = __c3 * __t120;
        let __t123 = __t2 * __t121;
        let __t124 = -__c3;
        let __t125 = -__c4;
        let __t126 = -__c5;
        let __t127 = -__c6;
        let __t128 = __t1 * __qd1;
        let __t129 = __c2 * __qd2;
        let __t130 = __t9 + __qd2 * __t128;
        let __t131 = __t1 * __qdd1 - __t10;
        let __t132 = -(__s2 * __qd2);
        let __t133 = -__t7;
        let __t134 = -((2159.0 / 5000.0) * __t128);
        let __t135 = -((2159.0 / 5000.0) * __c2);
        let __t136 = __c2 * __t14 + __t8 * __t135;
        let __t137 = __t13 + __t13;
        let __t138 = -__t137;
        let __t139 = __s2 * __t14 + __t7 * __t135;
        let __t140 = -__t139;
        let __t141 = __t8 * __t13 - (2159.0 / 5000.0) * __t131;
        let __t142 = __s2 * __t13 - (2159.0 / 5000.0) * __t132;
        let __t143 = (2159.0 / 5000.0) * __t7 - (2159.0 / 5000.0) * __t133;
        let __t144 = __t6 + __t14 * __t128 + __t8 * __t134;
        let __t145 = (981.0 / 100.0) * __t1 - (__t15 + __t7 * __t134);
        let __t146 = __t21 + __s3 * __t128;
        let __t147 = __s2 * __c3 + __c2 * __s3;
        let __t148 = __t2 * __t8;
        let __t149 = __t148 + __c3 * __t128;
        let __t150 = __t148 + __t7 * __t124;
        let __t151 = __s2 * __t2 + __c2 * __c3;
        let __t152 = __t21 + __s3 * __t133;
        let __t153 = __t148 + __c3 * __t133;
        let __t154 = -__t20;
        let __t155 = __c3 * __t130 + __s3 * __t131 - __t24 * __t149;
        let __t156 = __t23 - __t24 * __t150;
        let __t157 = __c3 * __t129 + __s3 * __t132 - __t24 * __t151;
        let __t158 = __t2 * __t130 + __c3 * __t131 + __t24 * __t146;
        let __t159 = __t26 + __t11 * __t124 + __t2 * __t12;
        let __t160 = __t2 * __t129 + __c3 * __t132 + __t24 * __t147;
        let __t161 = -((-(3001.0 / 20000.0)) * __t149);
        let __t162 = -((-(3001.0 / 20000.0)) * __t150);
        let __t163 = -((-(3001.0 / 20000.0)) * __t151);
        let __t164 = (203.0 / 10000.0) * __t149;
        let __t165 = (203.0 / 10000.0) * __t150;
        let __t166 = (203.0 / 10000.0) * __t151;
        let __t167 = (-(3001.0 / 20000.0)) * __t146;
        let __t168 = (-(3001.0 / 20000.0)) * __t147;
        let __t169 = __t33 - __t34;
        let __t170 = (203.0 / 10000.0) * __t20;
        let __t171 = __t169 - (-(3001.0 / 20000.0)) * __t154;
        let __t172 = __t31 * __t150 + __t22 * __t162 - (__t22 * __t34 + __t20 * __t30)
            + (203.0 / 10000.0) * __t159;
        let __t173 = (203.0 / 10000.0) * __t154 - __t170;
        let __t174 = __c3 * __t144 + __s3 * __t145 + __t25 * __t167
            - (__t32 * __t149 + __t22 * __t164) - (-(3001.0 / 20000.0)) * __t158;
        let __t175 = __t19 + __t25 * __t30 - (__t32 * __t150 + __t22 * __t165)
            - (-(3001.0 / 20000.0)) * __t159;
        let __t176 = __c3 * __t136 + __s3 * __t140 + __t25 * __t168
            - (__t32 * __t151 + __t22 * __t166) - (-(3001.0 / 20000.0)) * __t160;
        let __t177 = __c3 * __t138 + __t169 - (-(3001.0 / 20000.0)) * __t153;
        let __t178 = __t31 * __t149 + __t22 * __t161 - (__t34 * __t146 + __t20 * __t167)
            + (203.0 / 10000.0) * __t158 - __t141;
        let __t179 = __t31 * __t151 + __t22 * __t163 - (__t34 * __t147 + __t20 * __t168)
            + (203.0 / 10000.0) * __t160 - __t142;
        let __t180 = (203.0 / 10000.0) * __t153 - __t170 - __t143;
        let __t181 = __t2 * __t144 + __c3 * __t145 + __t32 * __t146 + __t20 * __t164
            - __t25 * __t161 + (-(3001.0 / 20000.0)) * __t155;
        let __t182 = __t17 * __t124 + __t2 * __t18 + __t35 + __t20 * __t165
            - __t25 * __t162 + (-(3001.0 / 20000.0)) * __t156;
        let __t183 = __t2 * __t136 + __c3 * __t140 + __t32 * __t147 + __t20 * __t166
            - __t25 * __t163 + (-(3001.0 / 20000.0)) * __t157;
        let __t184 = __t2 * __t138 + (-(3001.0 / 20000.0)) * __t152 - __t30;
        let __t185 = __c4 * __t146;
        let __t186 = __c4 * __t22;
        let __t187 = __c4 * __t147;
        let __t188 = __t3 * __t146;
        let __t189 = __t3 * __t22;
        let __t190 = __t3 * __t147;
        let __t191 = __t20 * __t125 + __t3 * __t25;
        let __t192 = -__t188;
        let __t193 = -__t189;
        let __t194 = -__t191;
        let __t195 = -__t190;
        let __t196 = __c4 * __qd4;
        let __t197 = __t3 * __qd4;
        let __t198 = __c4 * __t155 - __qd4 * __t192;
        let __t199 = __c4 * __t156 - __qd4 * __t193;
        let __t200 = __t43 - __qd4 * __t194;
        let __t201 = __c4 * __t157 - __qd4 * __t195;
        let __t202 = __c4 * __t152 - __t196;
        let __t203 = __t186 - __t196;
        let __t204 = __qd4 * __t185 - __t3 * __t155;
        let __t205 = __qd4 * __t186 - __t3 * __t156;
        let __t206 = __qd4 * __t41 - (__t28 * __t125 + __t3 * __t27);
        let __t207 = __qd4 * __t187 - __t3 * __t157;
        let __t208 = __t197 - __t3 * __t152;
        let __t209 = __t197 - __t189;
        let __t210 = -((2159.0 / 5000.0) * __t192);
        let __t211 = -((2159.0 / 5000.0) * __t193);
        let __t212 = -((2159.0 / 5000.0) * __t194);
        let __t213 = -((2159.0 / 5000.0) * __t195);
        let __t214 = -((2159.0 / 5000.0) * __c4);
        let __t215 = (2159.0 / 5000.0) * __t185;
        let __t216 = (2159.0 / 5000.0) * __t186;
        let __t217 = (2159.0 / 5000.0) * __t41;
        let __t218 = (2159.0 / 5000.0) * __t187;
        let __t219 = (2159.0 / 5000.0) * __t3;
        let __t220 = __t44 * __t219;
        let __t221 = __t49 * __t194 + __t42 * __t212 - (__t41 * __t50 + __t40 * __t217);
        let __t222 = __c4 * __t49 + __t42 * __t214 - (__t3 * __t50 + __t40 * __t219);
        let __t223 = __t44 * __t214;
        let __t224 = __t48 + __t217;
        let __t225 = __c4 * __t174 + __s4 * __t178 + __t50 * __t149 + __t44 * __t215
            - (2159.0 / 5000.0) * __t204;
        let __t226 = __c4 * __t175 + __s4 * __t172 + __t50 * __t150 + __t44 * __t216
            - (2159.0 / 5000.0) * __t205;
        let __t227 = __t39 + __t44 * __t217 - (2159.0 / 5000.0) * __t206;
        let __t228 = __c4 * __t176 + __s4 * __t179 + __t50 * __t151 + __t44 * __t218
            - (2159.0 / 5000.0) * __t207;
        let __t229 = __c4 * __t177 + __s4 * __t180 + __t220 - (2159.0 / 5000.0) * __t208;
        let __t230 = __c4 * __t171 + __s4 * __t173 + __t220 - (2159.0 / 5000.0) * __t209;
        let __t231 = __t181 + __t49 * __t192 + __t42 * __t210
            - (__t50 * __t185 + __t40 * __t215);
        let __t232 = __t182 + __t49 * __t193 + __t42 * __t211
            - (__t50 * __t186 + __t40 * __t216);
        let __t233 = __t183 + __t49 * __t195 + __t42 * __t213
            - (__t50 * __t187 + __t40 * __t218);
        let __t234 = __t184 + __t222;
        let __t235 = (2159.0 / 5000.0) * __t198 - (__t49 * __t149 + __t44 * __t210)
            - (__t3 * __t174 + __c4 * __t178);
        let __t236 = (2159.0 / 5000.0) * __t199 - (__t49 * __t150 + __t44 * __t211)
            - (__t3 * __t175 + __c4 * __t172);
        let __t237 = (2159.0 / 5000.0) * __t200 - __t44 * __t212
            - (__t36 * __t125 + __t3 * __t37);
        let __t238 = (2159.0 / 5000.0) * __t201 - (__t49 * __t151 + __t44 * __t213)
            - (__t3 * __t176 + __c4 * __t179);
        let __t239 = (2159.0 / 5000.0) * __t202 - __t223
            - (__t3 * __t177 + __c4 * __t180);
        let __t240 = (2159.0 / 5000.0) * __t203 - __t223
            - (__t3 * __t171 + __c4 * __t173);
        let __t241 = __c5 * __t225 + __s5 * __t231;
        let __t242 = __c5 * __t226 + __s5 * __t232;
        let __t243 = __c5 * __t227 + __s5 * __t221;
        let __t244 = __c5 * __t228 + __s5 * __t233;
        let __t245 = __c5 * __t229 + __s5 * __t234;
        let __t246 = __c5 * __t230 + __s5 * __t222;
        let __t247 = __t4 * __t225 + __c5 * __t231;
        let __t248 = __t4 * __t226 + __c5 * __t232;
        let __t249 = __t4 * __t227 + __c5 * __t221;
        let __t250 = __t51 * __t126 + __t4 * __t52;
        let __t251 = __t4 * __t228 + __c5 * __t233;
        let __t252 = __t4 * __t229 + __c5 * __t234;
        let __t253 = __t4 * __t230 + __c5 * __t222;
        let __t254 = -__t235;
        let __t255 = -__t236;
        let __t256 = -__t237;
        let __t257 = -__t238;
        let __t258 = -__t239;
        let __t259 = -__t240;
        let __t260 = -__t224;
        let __t261 = __c5 * __t41;
        let __t262 = __t3 * __c5;
        let __t263 = __c5 * __t185 + __s5 * __t149;
        let __t264 = __c5 * __t186 + __s5 * __t150;
        let __t265 = __c5 * __t187 + __s5 * __t151;
        let __t266 = __t4 * __t41;
        let __t267 = __t3 * __t4;
        let __t268 = __t4 * __t185 + __c5 * __t149;
        let __t269 = __t4 * __t186 + __c5 * __t150;
        let __t270 = __t40 * __t126 + __t4 * __t44;
        let __t271 = __t4 * __t187 + __c5 * __t151;
        let __t272 = -__t204;
        let __t273 = -__t205;
        let __t274 = -__t206;
        let __t275 = -__t207;
        let __t276 = -__t208;
        let __t277 = -__t209;
        let __t278 = -__t40;
        let __t279 = __t59 * __t267;
        let __t280 = __c5 * __t198 + __s5 * __t158 - __t59 * __t268;
        let __t281 = __c5 * __t199 + __s5 * __t159 - __t59 * __t269;
        let __t282 = __c5 * __t200 - __t59 * __t266;
        let __t283 = __t4 * __t46 + __c5 * __t45 - __t59 * __t270;
        let __t284 = __c5 * __t201 + __s5 * __t160 - __t59 * __t271;
        let __t285 = __c5 * __t202 + __s5 * __t153 - __t279;
        let __t286 = __c5 * __t203 + __s5 * __t154 - __t279;
        let __t287 = __t261 - __c5 * __t59;
        let __t288 = __c6 * __t58;
        let __t289 = __s5 * __c6;
        let __t290 = __c6 * __t263 + __s6 * __t188;
        let __t291 = __c6 * __t264 + __s6 * __t189;
        let __t292 = __c6 * __t261 + __s6 * __t191;
        let __t293 = __c6 * __t265 + __s6 * __t190;
        let __t294 = __c6 * __t262 + __s6 * __t125;
        let __t295 = __t5 * __t58;
        let __t296 = __s5 * __t5;
        let __t297 = __t5 * __t263 + __c6 * __t188;
        let __t298 = __t5 * __t264 + __c6 * __t189;
        let __t299 = __t5 * __t261 + __c6 * __t191;
        let __t300 = __t57 * __t127 + __t5 * __t60;
        let __t301 = __t5 * __t265 + __c6 * __t190;
        let __t302 = __t5 * __t262 + __c6 * __t125;
        let __t303 = __qd6 * __t302;
        let __t304 = __qd6 * __t294;
        let __t305 = (91.0 / 400.0) * __t128;
        let __t306 = (91.0 / 400.0) * __c2;
        let __t307 = -__t69;
        let __t308 = -((91.0 / 400.0) * __s2);
        let __t309 = (3.0 / 500.0) * __t8;
        let __t310 = __t309 - (-(1819.0 / 5000.0)) * __t128;
        let __t311 = (3.0 / 500.0) * __s2 - (-(1819.0 / 5000.0)) * __c2;
        let __t312 = (87.0 / 5.0)
            * (__t144 + __t73 * __t128 + __t8 * __t310 - __qd2 * __t307
                + (91.0 / 400.0) * __t131);
        let __t313 = (87.0 / 5.0)
            * (__t136 + __c2 * __t73 + __t8 * __t311 - __qd2 * __t308
                + (91.0 / 400.0) * __t132);
        let __t314 = (87.0 / 5.0) * ((91.0 / 400.0) * __t133 - (__t71 + __t72) - __t137);
        let __t315 = (87.0 / 5.0)
            * (__t145 + __qd2 * __t305 - (__t74 + __t7 * __t310)
                - (91.0 / 400.0) * __t130);
        let __t316 = (87.0 / 5.0)
            * (__qd2 * __t306 - (__s2 * __t73 + __t7 * __t311) - (91.0 / 400.0) * __t129
                - __t139);
        let __t317 = (87.0 / 5.0) * (__t70 + (-(3.0 / 500.0)) * __qd2 - __t69);
        let __t318 = (87.0 / 5.0)
            * (__t141 + __t8 * __t72 + __t7 * __t307 - (__t70 * __t128 + __t8 * __t305)
                + (3.0 / 500.0) * __t130 - (-(1819.0 / 5000.0)) * __t131);
        let __t319 = (87.0 / 5.0)
            * (__t142 + __s2 * __t72 + __t7 * __t308 - (__c2 * __t70 + __t8 * __t306)
                + (3.0 / 500.0) * __t129 - (-(1819.0 / 5000.0)) * __t132);
        let __t320 = (87.0 / 5.0)
            * (__t143 + (-(1819.0 / 5000.0)) * __t7 - (-(3.0 / 500.0)) * __t8 + __t309
                - (-(1819.0 / 5000.0)) * __t133);
        let __t321 = -((-(141.0 / 10000.0)) * __t149);
        let __t322 = -((-(141.0 / 10000.0)) * __t150);
        let __t323 = -((-(141.0 / 10000.0)) * __t151);
        let __t324 = (7.0 / 100.0) * __t22;
        let __t325 = (-(203.0 / 10000.0)) * __t149 - (7.0 / 100.0) * __t146;
        let __t326 = (-(203.0 / 10000.0)) * __t150 - __t324;
        let __t327 = (-(203.0 / 10000.0)) * __t151 - (7.0 / 100.0) * __t147;
        let __t328 = (-(141.0 / 10000.0)) * __t146;
        let __t329 = (-(141.0 / 10000.0)) * __t147;
        let __t330 = __t79 - __t80;
        let __t331 = (-(7.0 / 100.0)) * __t22 - (-(203.0 / 10000.0)) * __t20;
        let __t332 = (-(7.0 / 100.0)) * __t25 - __t77;
        let __t333 = (24.0 / 5.0)
            * (__t174 + __t25 * __t328 - (__t78 * __t149 + __t22 * __t325)
                - (-(141.0 / 10000.0)) * __t158);
        let __t334 = (24.0 / 5.0)
            * (__t175 + __t25 * __t76 - (__t78 * __t150 + __t22 * __t326)
                - (-(141.0 / 10000.0)) * __t159);
        let __t335 = (24.0 / 5.0)
            * (__t176 + __t25 * __t329 - (__t78 * __t151 + __t22 * __t327)
                - (-(141.0 / 10000.0)) * __t160);
        let __t336 = (24.0 / 5.0) * (__t177 + __t330 - (-(141.0 / 10000.0)) * __t153);
        let __t337 = (24.0 / 5.0) * (__t171 + __t330 - (-(141.0 / 10000.0)) * __t154);
        let __t338 = (24.0 / 5.0)
            * (__t178 + __t77 * __t149 + __t22 * __t321
                - (__t80 * __t146 + __t20 * __t328) + (-(203.0 / 10000.0)) * __t158
                - (7.0 / 100.0) * __t155);
        let __t339 = (24.0 / 5.0)
            * (__t172 + __t77 * __t150 + __t22 * __t322 - (__t22 * __t80 + __t20 * __t76)
                + (-(203.0 / 10000.0)) * __t159 - (7.0 / 100.0) * __t156);
        let __t340 = (24.0 / 5.0)
            * (__t179 + __t77 * __t151 + __t22 * __t323
                - (__t80 * __t147 + __t20 * __t329) + (-(203.0 / 10000.0)) * __t160
                - (7.0 / 100.0) * __t157);
        let __t341 = (24.0 / 5.0)
            * (__t180 + __t331 + (-(203.0 / 10000.0)) * __t153 - (7.0 / 100.0) * __t152);
        let __t342 = (24.0 / 5.0)
            * (__t173 + __t331 + (-(203.0 / 10000.0)) * __t154 - __t324);
        let __t343 = (24.0 / 5.0)
            * (__t181 + __t78 * __t146 + __t20 * __t325 - __t25 * __t321
                + (-(141.0 / 10000.0)) * __t155);
        let __t344 = (24.0 / 5.0)
            * (__t182 + __t81 + __t20 * __t326 - __t25 * __t322
                + (-(141.0 / 10000.0)) * __t156);
        let __t345 = (24.0 / 5.0)
            * (__t183 + __t78 * __t147 + __t20 * __t327 - __t25 * __t323
                + (-(141.0 / 10000.0)) * __t157);
        let __t346 = (24.0 / 5.0) * (__t184 + (-(141.0 / 10000.0)) * __t152 - __t332);
        let __t347 = (24.0 / 5.0) * (__t76 - __t332);
        let __t348 = -((19.0 / 1000.0) * __t192);
        let __t349 = -((19.0 / 1000.0) * __t193);
        let __t350 = -((19.0 / 1000.0) * __t194);
        let __t351 = -((19.0 / 1000.0) * __t195);
        let __t352 = -((19.0 / 1000.0) * __c4);
        let __t353 = (19.0 / 1000.0) * __t185;
        let __t354 = (19.0 / 1000.0) * __t186;
        let __t355 = (19.0 / 1000.0) * __t41;
        let __t356 = (19.0 / 1000.0) * __t187;
        let __t357 = (19.0 / 1000.0) * __t3;
        let __t358 = __t44 * __t357;
        let __t359 = __c4 * __t86 + __t42 * __t352 - (__t3 * __t87 + __t40 * __t357);
        let __t360 = __t44 * __t352;
        let __t361 = (41.0 / 50.0)
            * (__t225 + __t87 * __t149 + __t44 * __t353 - (19.0 / 1000.0) * __t204);
        let __t362 = (41.0 / 50.0)
            * (__t226 + __t87 * __t150 + __t44 * __t354 - (19.0 / 1000.0) * __t205);
        let __t363 = (41.0 / 50.0)
            * (__t227 + __t44 * __t355 - (19.0 / 1000.0) * __t206);
        let __t364 = (41.0 / 50.0)
            * (__t228 + __t87 * __t151 + __t44 * __t356 - (19.0 / 1000.0) * __t207);
        let __t365 = (41.0 / 50.0) * (__t229 + __t358 - (19.0 / 1000.0) * __t208);
        let __t366 = (41.0 / 50.0) * (__t230 + __t358 - (19.0 / 1000.0) * __t209);
        let __t367 = (41.0 / 50.0)
            * (__t235 + (19.0 / 1000.0) * __t198 - (__t86 * __t149 + __t44 * __t348));
        let __t368 = (41.0 / 50.0)
            * (__t236 + (19.0 / 1000.0) * __t199 - (__t86 * __t150 + __t44 * __t349));
        let __t369 = (41.0 / 50.0)
            * (__t237 + (19.0 / 1000.0) * __t200 - __t44 * __t350);
        let __t370 = (41.0 / 50.0)
            * (__t238 + (19.0 / 1000.0) * __t201 - (__t86 * __t151 + __t44 * __t351));
        let __t371 = (41.0 / 50.0) * (__t239 + (19.0 / 1000.0) * __t202 - __t360);
        let __t372 = (41.0 / 50.0) * (__t240 + (19.0 / 1000.0) * __t203 - __t360);
        let __t373 = (41.0 / 50.0) * (__t224 + __t85 + __t355);
        let __t374 = (4.0 / 125.0) * __t297;
        let __t375 = (4.0 / 125.0) * __t298;
        let __t376 = (4.0 / 125.0) * __t299;
        let __t377 = (4.0 / 125.0) * __t295;
        let __t378 = (4.0 / 125.0) * __t300;
        let __t379 = (4.0 / 125.0) * __t301;
        let __t380 = (4.0 / 125.0) * __t302;
        let __t381 = (4.0 / 125.0) * __t296;
        let __t382 = (4.0 / 125.0) * __t127;
        let __t383 = -((4.0 / 125.0) * __t290);
        let __t384 = -((4.0 / 125.0) * __t291);
        let __t385 = -((4.0 / 125.0) * __t292);
        let __t386 = -((4.0 / 125.0) * __t288);
        let __t387 = -__t91;
        let __t388 = -((4.0 / 125.0) * __t293);
        let __t389 = -((4.0 / 125.0) * __t294);
        let __t390 = -((4.0 / 125.0) * __t289);
        let __t391 = -((4.0 / 125.0) * __t5);
        let __t392 = __t93 * __t267 + __t67 * __t389;
        let __t393 = __t91 * __t267 + __t67 * __t380;
        let __t394 = __t93 * __t294 + __t64 * __t389 - (__t91 * __t302 + __t65 * __t380);
        let __t395 = (9.0 / 100.0)
            * (__c6 * __t241 + __s6 * __t254
                + (4.0 / 125.0) * (__t5 * __t280 + __c6 * __t272 - __qd6 * __t290)
                - (__t93 * __t268 + __t67 * __t383));
        let __t396 = (9.0 / 100.0)
            * (__c6 * __t242 + __s6 * __t255
                + (4.0 / 125.0) * (__t5 * __t281 + __c6 * __t273 - __qd6 * __t291)
                - (__t93 * __t269 + __t67 * __t384));
        let __t397 = (9.0 / 100.0)
            * (__c6 * __t243 + __s6 * __t256
                + (4.0 / 125.0) * (__t5 * __t282 + __c6 * __t274 - __qd6 * __t292)
                - (__t93 * __t266 + __t67 * __t385));
        let __t398 = (9.0 / 100.0)
            * (__c6 * __t55 + (4.0 / 125.0) * (__t5 * __t283 - __qd6 * __t288)
                - (__t93 * __t270 + __t67 * __t386));
        let __t399 = (9.0 / 100.0)
            * (__t63 + (4.0 / 125.0) * (__t62 * __t127 + __t5 * __t61 - __t68)
                - __t67 * __t387);
        let __t400 = (9.0 / 100.0)
            * (__c6 * __t244 + __s6 * __t257
                + (4.0 / 125.0) * (__t5 * __t284 + __c6 * __t275 - __qd6 * __t293)
                - (__t93 * __t271 + __t67 * __t388));
        let __t401 = (9.0 / 100.0)
            * (__c6 * __t245 + __s6 * __t258
                + (4.0 / 125.0) * (__t5 * __t285 + __c6 * __t276 - __t304) - __t392);
        let __t402 = (9.0 / 100.0)
            * (__c6 * __t246 + __s6 * __t259
                + (4.0 / 125.0) * (__t5 * __t286 + __c6 * __t277 - __t304) - __t392);
        let __t403 = (9.0 / 100.0)
            * (__s6 * __t260
                + (4.0 / 125.0) * (__t5 * __t287 + __c6 * __t278 - __qd6 * __t289)
                - (__c5 * __t93 + __t67 * __t390));
        let __t404 = (9.0 / 100.0)
            * ((4.0 / 125.0) * (__t295 - __t5 * __qd6) - __t67 * __t391);
        let __t405 = (9.0 / 100.0) * (__t92 + (4.0 / 125.0) * (-__t64));
        let __t406 = (9.0 / 100.0)
            * (__t5 * __t241 + __c6 * __t254 + __t91 * __t268 + __t67 * __t374
                - (4.0 / 125.0) * (__c6 * __t280 + __s6 * __t272 + __qd6 * __t297));
        let __t407 = (9.0 / 100.0)
            * (__t5 * __t242 + __c6 * __t255 + __t91 * __t269 + __t67 * __t375
                - (4.0 / 125.0) * (__c6 * __t281 + __s6 * __t273 + __qd6 * __t298));
        let __t408 = (9.0 / 100.0)
            * (__t5 * __t243 + __c6 * __t256 + __t91 * __t266 + __t67 * __t376
                - (4.0 / 125.0) * (__c6 * __t282 + __s6 * __t274 + __qd6 * __t299));
        let __t409 = (9.0 / 100.0)
            * (__t5 * __t55 + __t91 * __t270 + __t67 * __t377
                - (4.0 / 125.0) * (__c6 * __t283 + __qd6 * __t295));
        let __t410 = (9.0 / 100.0)
            * (__t54 * __t127 + __t5 * __t56 + __t67 * __t378
                - (4.0 / 125.0) * (__t66 + __qd6 * __t300));
        let __t411 = (9.0 / 100.0)
            * (__t5 * __t244 + __c6 * __t257 + __t91 * __t271 + __t67 * __t379
                - (4.0 / 125.0) * (__c6 * __t284 + __s6 * __t275 + __qd6 * __t301));
        let __t412 = (9.0 / 100.0)
            * (__t5 * __t245 + __c6 * __t258 + __t393
                - (4.0 / 125.0) * (__c6 * __t285 + __s6 * __t276 + __t303));
        let __t413 = (9.0 / 100.0)
            * (__t5 * __t246 + __c6 * __t259 + __t393
                - (4.0 / 125.0) * (__c6 * __t286 + __s6 * __t277 + __t303));
        let __t414 = (9.0 / 100.0)
            * (__c6 * __t260 + __c5 * __t91 + __t67 * __t381
                - (4.0 / 125.0) * (__c6 * __t287 + __s6 * __t278 + __qd6 * __t296));
        let __t415 = (9.0 / 100.0)
            * (__t67 * __t382 - (4.0 / 125.0) * (__t288 + __qd6 * __t127));
        let __t416 = (9.0 / 100.0)
            * (__t65 * __t93 + __t64 * __t387 - (__t91 * __t300 + __t65 * __t378));
        let __t417 = (9.0 / 100.0)
            * (__t93 * __t289 + __t64 * __t390 - (__t91 * __t296 + __t65 * __t381));
        let __t418 = (9.0 / 100.0)
            * (__t5 * __t93 + __t64 * __t391 - (__t91 * __t127 + __t65 * __t382));
        let __t419 = -((4.0 / 125.0) * __t406);
        let __t420 = -((4.0 / 125.0) * __t407);
        let __t421 = -((4.0 / 125.0) * __t408);
        let __t422 = -((4.0 / 125.0) * __t409);
        let __t423 = -((4.0 / 125.0) * __t410);
        let __t424 = -((4.0 / 125.0) * __t411);
        let __t425 = -((4.0 / 125.0) * __t412);
        let __t426 = -((4.0 / 125.0) * __t413);
        let __t427 = -((4.0 / 125.0) * __t414);
        let __t428 = -((4.0 / 125.0) * __t415);
        let __t429 = (4.0 / 125.0) * __t395;
        let __t430 = (4.0 / 125.0) * __t396;
        let __t431 = (4.0 / 125.0) * __t397;
        let __t432 = (4.0 / 125.0) * __t398;
        let __t433 = (4.0 / 125.0) * __t399;
        let __t434 = (4.0 / 125.0) * __t400;
        let __t435 = (4.0 / 125.0) * __t401;
        let __t436 = (4.0 / 125.0) * __t402;
        let __t437 = (4.0 / 125.0) * __t403;
        let __t438 = (4.0 / 125.0) * __t404;
        let __t439 = (4.0 / 125.0) * __t405;
        let __t440 = __c6 * __t405;
        let __t441 = __t5 * __t94 + __c6 * __t399 + __t95 * __t127 + __t5 * __t410;
        let __t442 = __c6 * __t403 + __t5 * __t414;
        let __t443 = __c6 * __t404 + __t5 * __t415;
        let __t444 = __s6 * __t405;
        let __t445 = __s6 * __t398 + __c6 * __t409;
        let __t446 = __t98 + __s6 * __t399 + __t99 + __c6 * __t410;
        let __t447 = __s6 * __t404 + __c6 * __t415;
        let __t448 = __t5 * __t439;
        let __t449 = __c6 * __t419 + __t5 * __t429;
        let __t450 = __c6 * __t420 + __t5 * __t430;
        let __t451 = __c6 * __t421 + __t5 * __t431;
        let __t452 = __c6 * __t422 + __t5 * __t432;
        let __t453 = __t5 * __t96 + __c6 * __t423 + __t97 * __t127 + __t5 * __t433;
        let __t454 = __c6 * __t424 + __t5 * __t434;
        let __t455 = __c6 * __t425 + __t5 * __t435;
        let __t456 = __c6 * __t426 + __t5 * __t436;
        let __t457 = __c6 * __t427 + __t5 * __t437;
        let __t458 = __c6 * __t428 + __t5 * __t438;
        let __t459 = __s6 * __t419 + __c6 * __t429;
        let __t460 = __s6 * __t420 + __c6 * __t430;
        let __t461 = __s6 * __t421 + __c6 * __t431;
        let __t462 = __s6 * __t424 + __c6 * __t434;
        let __t463 = __s6 * __t425 + __c6 * __t435;
        let __t464 = __s6 * __t426 + __c6 * __t436;
        let __t465 = (17.0 / 50.0) * __t241 + __c6 * __t395 + __t5 * __t406;
        let __t466 = (17.0 / 50.0) * __t242 + __c6 * __t396 + __t5 * __t407;
        let __t467 = (17.0 / 50.0) * __t243 + __c6 * __t397 + __t5 * __t408;
        let __t468 = __t90 + __c6 * __t398 + __t5 * __t409;
        let __t469 = (17.0 / 50.0) * __t244 + __c6 * __t400 + __t5 * __t411;
        let __t470 = (17.0 / 50.0) * __t245 + __c6 * __t401 + __t5 * __t412;
        let __t471 = (17.0 / 50.0) * __t246 + __c6 * __t402 + __t5 * __t413;
        let __t472 = (17.0 / 50.0) * __t247
            + (9.0 / 100.0)
                * (__t247 + __t93 * __t290 + __t64 * __t383
                    - (__t91 * __t297 + __t65 * __t374));
        let __t473 = (17.0 / 50.0) * __t248
            + (9.0 / 100.0)
                * (__t248 + __t93 * __t291 + __t64 * __t384
                    - (__t91 * __t298 + __t65 * __t375));
        let __t474 = (17.0 / 50.0) * __t249
            + (9.0 / 100.0)
                * (__t249 + __t93 * __t292 + __t64 * __t385
                    - (__t91 * __t299 + __t65 * __t376));
        let __t475 = (17.0 / 50.0) * __t250
            + (9.0 / 100.0)
                * (__t250 + __t93 * __t288 + __t64 * __t386
                    - (__t91 * __t295 + __t65 * __t377));
        let __t476 = (17.0 / 50.0) * __t251
            + (9.0 / 100.0)
                * (__t251 + __t93 * __t293 + __t64 * __t388
                    - (__t91 * __t301 + __t65 * __t379));
        let __t477 = (17.0 / 50.0) * __t252 + (9.0 / 100.0) * (__t252 + __t394);
        let __t478 = (17.0 / 50.0) * __t253 + (9.0 / 100.0) * (__t253 + __t394);
        let __dtau5_dq2 = -__t459;
        let __dtau5_dq3 = -__t460;
        let __dtau5_dq4 = -__t461;
        let __dtau5_dq5 = -(__s6 * __t422 + __c6 * __t432);
        let __dtau5_dq6 = -(__t100 + __s6 * __t423 + __t101 + __c6 * __t433);
        let __dtau5_dqd1 = -__t462;
        let __dtau5_dqd2 = -__t463;
        let __dtau5_dqd3 = -__t464;
        let __dtau5_dqd4 = -(__s6 * __t427 + __c6 * __t437);
        let __dtau5_dqd5 = -(__s6 * __t428 + __c6 * __t438);
        let __dtau5_dqd6 = -(__c6 * __t439);
        let __t479 = __c5 * __t440;
        let __t480 = __t4 * __t103 + __c5 * __t468 + __t104 * __t126 + __t4 * __t475;
        let __t481 = __c5 * __t441 + __t4 * __t416;
        let __t482 = __c5 * __t442 + __t4 * __t417;
        let __t483 = __c5 * __t443 + __t4 * __t418;
        let __t484 = __s5 * __t440;
        let __t485 = __t105 + __s5 * __t468 + __t106 + __c5 * __t475;
        let __t486 = __s5 * __t441 + __c5 * __t416;
        let __t487 = __s5 * __t442 + __c5 * __t417;
        let __t488 = __s5 * __t443 + __c5 * __t418;
        let __dtau4_dq2 = __s5 * __t449;
        let __dtau4_dq3 = __s5 * __t450;
        let __dtau4_dq4 = __s5 * __t451;
        let __dtau4_dq5 = __t107 + __s5 * __t452;
        let __dtau4_dq6 = __s5 * __t453;
        let __dtau4_dqd1 = __s5 * __t454;
        let __dtau4_dqd2 = __s5 * __t455;
        let __dtau4_dqd3 = __s5 * __t456;
        let __dtau4_dqd4 = __s5 * __t457;
        let __dtau4_dqd5 = __s5 * __t458;
        let __dtau4_dqd6 = __s5 * __t448;
        let __t489 = __t361 + __c5 * __t465 + __t4 * __t472;
        let __t490 = __t362 + __c5 * __t466 + __t4 * __t473;
        let __t491 = __t363 + __c5 * __t467 + __t4 * __t474;
        let __t492 = __t364 + __c5 * __t469 + __t4 * __t476;
        let __t493 = __t365 + __c5 * __t470 + __t4 * __t477;
        let __t494 = __t366 + __c5 * __t471 + __t4 * __t478;
        let __t495 = (41.0 / 50.0)
            * (__t221 + __t86 * __t194 + __t42 * __t350
                - (__t41 * __t87 + __t40 * __t355)) + __s5 * __t467 + __c5 * __t474;
        let __t496 = __t367 - ((17.0 / 50.0) * __t254 + __s6 * __t395 + __c6 * __t406);
        let __t497 = __t368 - ((17.0 / 50.0) * __t255 + __s6 * __t396 + __c6 * __t407);
        let __t498 = __t369 - ((17.0 / 50.0) * __t256 + __s6 * __t397 + __c6 * __t408);
        let __t499 = __t370 - ((17.0 / 50.0) * __t257 + __s6 * __t400 + __c6 * __t411);
        let __t500 = __t371 - ((17.0 / 50.0) * __t258 + __s6 * __t401 + __c6 * __t412);
        let __t501 = __t372 - ((17.0 / 50.0) * __t259 + __s6 * __t402 + __c6 * __t413);
        let __t502 = __t373 - ((17.0 / 50.0) * __t260 + __s6 * __t403 + __c6 * __t414);
        let __t503 = (19.0 / 1000.0) * __t367 + __c5 * __t449
            + (2159.0 / 5000.0) * __t496;
        let __t504 = (19.0 / 1000.0) * __t368 + __c5 * __t450
            + (2159.0 / 5000.0) * __t497;
        let __t505 = (19.0 / 1000.0) * __t369 + __c5 * __t451
            + (2159.0 / 5000.0) * __t498;
        let __t506 = __t4 * __t102 + __c5 * __t452 + (2159.0 / 5000.0) * (-__t445);
        let __t507 = __c5 * __t453 + (2159.0 / 5000.0) * (-__t446);
        let __t508 = (19.0 / 1000.0) * __t370 + __c5 * __t454
            + (2159.0 / 5000.0) * __t499;
        let __t509 = (19.0 / 1000.0) * __t371 + __c5 * __t455
            + (2159.0 / 5000.0) * __t500;
        let __t510 = (19.0 / 1000.0) * __t372 + __c5 * __t456
            + (2159.0 / 5000.0) * __t501;
        let __t511 = (19.0 / 1000.0) * __t373 + __c5 * __t457
            + (2159.0 / 5000.0) * __t502;
        let __t512 = __c5 * __t458 + (2159.0 / 5000.0) * (-__t447);
        let __t513 = __c5 * __t448 + (2159.0 / 5000.0) * (-__t444);
        let __t514 = -__t496;
        let __t515 = -__t497;
        let __t516 = -__t498;
        let __t517 = -__t499;
        let __t518 = -__t500;
        let __t519 = -__t501;
        let __t520 = -__t502;
        let __t521 = __t3 * __t108 + __c4 * __t491 + __t111 * __t125 + __t3 * __t516;
        let __t522 = __c4 * __t480 + __t3 * __t445;
        let __t523 = __c4 * __t481 + __t3 * __t446;
        let __t524 = __c4 * __t482 + __t3 * __t520;
        let __t525 = __c4 * __t483 + __t3 * __t447;
        let __t526 = __c4 * __t479 + __t3 * __t444;
        let __t527 = __t112 + __s4 * __t491 + __t113 + __c4 * __t516;
        let __t528 = __s4 * __t480 + __c4 * __t445;
        let __t529 = __s4 * __t481 + __c4 * __t446;
        let __t530 = __s4 * __t482 + __c4 * __t520;
        let __t531 = __s4 * __t483 + __c4 * __t447;
        let __t532 = __s4 * __t479 + __c4 * __t444;
        let __t533 = -(-((19.0 / 1000.0) * __t361) - __t459
            - (2159.0 / 5000.0) * __t489);
        let __t534 = -(-((19.0 / 1000.0) * __t362) - __t460
            - (2159.0 / 5000.0) * __t490);
        let __t535 = -(-((19.0 / 1000.0) * __t363) - __t461
            - (2159.0 / 5000.0) * __t491);
        let __t536 = -(__dtau5_dq5 - (2159.0 / 5000.0) * __t480);
        let __t537 = -(__dtau5_dq6 - (2159.0 / 5000.0) * __t481);
        let __t538 = -(-((19.0 / 1000.0) * __t364) - __t462
            - (2159.0 / 5000.0) * __t492);
        let __t539 = -(-((19.0 / 1000.0) * __t365) - __t463
            - (2159.0 / 5000.0) * __t493);
        let __t540 = -(-((19.0 / 1000.0) * __t366) - __t464
            - (2159.0 / 5000.0) * __t494);
        let __t541 = -(__dtau5_dqd4 - (2159.0 / 5000.0) * __t482);
        let __t542 = -(__dtau5_dqd5 - (2159.0 / 5000.0) * __t483);
        let __t543 = -(__dtau5_dqd6 - (2159.0 / 5000.0) * __t479);
        let __t544 = __t333 + __c4 * __t489 + __t3 * __t514;
        let __t545 = __t334 + __c4 * __t490 + __t3 * __t515;
        let __t546 = __t335 + __c4 * __t492 + __t3 * __t517;
        let __t547 = __t336 + __c4 * __t493 + __t3 * __t518;
        let __t548 = __t337 + __c4 * __t494 + __t3 * __t519;
        let __t549 = __t338 + __s4 * __t489 + __c4 * __t514;
        let __t550 = __t339 + __s4 * __t490 + __c4 * __t515;
        let __t551 = __t340 + __s4 * __t492 + __c4 * __t517;
        let __t552 = __t341 + __s4 * __t493 + __c4 * __t518;
        let __t553 = __t342 + __s4 * __t494 + __c4 * __t519;
        let __t554 = __t343
            + (41.0 / 50.0)
                * (__t231 + __t86 * __t192 + __t42 * __t348
                    - (__t87 * __t185 + __t40 * __t353)) + __s5 * __t465 + __c5 * __t472;
        let __t555 = __t344
            + (41.0 / 50.0)
                * (__t232 + __t86 * __t193 + __t42 * __t349
                    - (__t87 * __t186 + __t40 * __t354)) + __s5 * __t466 + __c5 * __t473;
        let __t556 = __t345
            + (41.0 / 50.0)
                * (__t233 + __t86 * __t195 + __t42 * __t351
                    - (__t87 * __t187 + __t40 * __t356)) + __s5 * __t469 + __c5 * __t476;
        let __t557 = __t346 + (41.0 / 50.0) * (__t234 + __t359) + __s5 * __t470
            + __c5 * __t477;
        let __t558 = __t347 + (41.0 / 50.0) * (__t222 + __t359) + __s5 * __t471
            + __c5 * __t478;
        let __t559 = (-(141.0 / 10000.0)) * __t343 - (7.0 / 100.0) * __t338
            + __c4 * __t503 + __t3 * __t533 + (-(3001.0 / 20000.0)) * __t554;
        let __t560 = (-(141.0 / 10000.0)) * __t344 - (7.0 / 100.0) * __t339
            + __c4 * __t504 + __t3 * __t534 + (-(3001.0 / 20000.0)) * __t555;
        let __t561 = __t3 * __t110 + __c4 * __t505 + __t114 * __t125 + __t3 * __t535
            + (-(3001.0 / 20000.0)) * __t495;
        let __t562 = __c4 * __t506 + __t3 * __t536 + (-(3001.0 / 20000.0)) * __t485;
        let __t563 = __c4 * __t507 + __t3 * __t537 + (-(3001.0 / 20000.0)) * __t486;
        let __t564 = (-(141.0 / 10000.0)) * __t345 - (7.0 / 100.0) * __t340
            + __c4 * __t508 + __t3 * __t538 + (-(3001.0 / 20000.0)) * __t556;
        let __t565 = (-(141.0 / 10000.0)) * __t346 - (7.0 / 100.0) * __t341
            + __c4 * __t509 + __t3 * __t539 + (-(3001.0 / 20000.0)) * __t557;
        let __t566 = (-(141.0 / 10000.0)) * __t347 - (7.0 / 100.0) * __t342
            + __c4 * __t510 + __t3 * __t540 + (-(3001.0 / 20000.0)) * __t558;
        let __t567 = __c4 * __t511 + __t3 * __t541 + (-(3001.0 / 20000.0)) * __t487;
        let __t568 = __c4 * __t512 + __t3 * __t542 + (-(3001.0 / 20000.0)) * __t488;
        let __t569 = __c4 * __t513 + __t3 * __t543 + (-(3001.0 / 20000.0)) * __t484;
        let __t570 = (7.0 / 100.0) * __t333 - (-(203.0 / 10000.0)) * __t343
            + __s4 * __t503 + __c4 * __t533 - (203.0 / 10000.0) * __t554;
        let __t571 = (7.0 / 100.0) * __t334 - (-(203.0 / 10000.0)) * __t344
            + __s4 * __t504 + __c4 * __t534 - (203.0 / 10000.0) * __t555;
        let __t572 = __t115 + __s4 * __t505 + __t116 + __c4 * __t535
            - (203.0 / 10000.0) * __t495;
        let __t573 = __s4 * __t506 + __c4 * __t536 - (203.0 / 10000.0) * __t485;
        let __t574 = __s4 * __t507 + __c4 * __t537 - (203.0 / 10000.0) * __t486;
        let __t575 = (7.0 / 100.0) * __t335 - (-(203.0 / 10000.0)) * __t345
            + __s4 * __t508 + __c4 * __t538 - (203.0 / 10000.0) * __t556;
        let __t576 = (7.0 / 100.0) * __t336 - (-(203.0 / 10000.0)) * __t346
            + __s4 * __t509 + __c4 * __t539 - (203.0 / 10000.0) * __t557;
        let __t577 = (7.0 / 100.0) * __t337 - (-(203.0 / 10000.0)) * __t347
            + __s4 * __t510 + __c4 * __t540 - (203.0 / 10000.0) * __t558;
        let __t578 = __s4 * __t511 + __c4 * __t541 - (203.0 / 10000.0) * __t487;
        let __t579 = __s4 * __t512 + __c4 * __t542 - (203.0 / 10000.0) * __t488;
        let __t580 = __s4 * __t513 + __c4 * __t543 - (203.0 / 10000.0) * __t484;
        let __t581 = (-(203.0 / 10000.0)) * __t338 - (-(141.0 / 10000.0)) * __t333
            + __dtau4_dq2 + (203.0 / 10000.0) * __t549 - (-(3001.0 / 20000.0)) * __t544;
        let __t582 = (-(203.0 / 10000.0)) * __t339 - (-(141.0 / 10000.0)) * __t334
            + __dtau4_dq3 + (203.0 / 10000.0) * __t550 - (-(3001.0 / 20000.0)) * __t545;
        let __t583 = __dtau4_dq4 + (203.0 / 10000.0) * __t527
            - (-(3001.0 / 20000.0)) * __t521;
        let __t584 = __dtau4_dq5 + (203.0 / 10000.0) * __t528
            - (-(3001.0 / 20000.0)) * __t522;
        let __t585 = __dtau4_dq6 + (203.0 / 10000.0) * __t529
            - (-(3001.0 / 20000.0)) * __t523;
        let __t586 = (-(203.0 / 10000.0)) * __t340 - (-(141.0 / 10000.0)) * __t335
            + __dtau4_dqd1 + (203.0 / 10000.0) * __t551 - (-(3001.0 / 20000.0)) * __t546;
        let __t587 = (-(203.0 / 10000.0)) * __t341 - (-(141.0 / 10000.0)) * __t336
            + __dtau4_dqd2 + (203.0 / 10000.0) * __t552 - (-(3001.0 / 20000.0)) * __t547;
        let __t588 = (-(203.0 / 10000.0)) * __t342 - (-(141.0 / 10000.0)) * __t337
            + __dtau4_dqd3 + (203.0 / 10000.0) * __t553 - (-(3001.0 / 20000.0)) * __t548;
        let __t589 = __dtau4_dqd4 + (203.0 / 10000.0) * __t530
            - (-(3001.0 / 20000.0)) * __t524;
        let __t590 = __dtau4_dqd5 + (203.0 / 10000.0) * __t531
            - (-(3001.0 / 20000.0)) * __t525;
        let __t591 = __dtau4_dqd6 + (203.0 / 10000.0) * __t532
            - (-(3001.0 / 20000.0)) * __t526;
        let __dtau3_dq2 = -__t570;
        let __dtau3_dq3 = -__t571;
        let __dtau3_dq4 = -__t572;
        let __dtau3_dq5 = -__t573;
        let __dtau3_dq6 = -__t574;
        let __dtau3_dqd1 = -__t575;
        let __dtau3_dqd2 = -__t576;
        let __dtau3_dqd3 = -__t577;
        let __dtau3_dqd4 = -__t578;
        let __dtau3_dqd5 = -__t579;
        let __dtau3_dqd6 = -__t580;
        let __dtau2_dq2 = (-(1819.0 / 5000.0)) * __t315 - (3.0 / 500.0) * __t312 - __t570
            + (2159.0 / 5000.0) * (__t315 + __s3 * __t544 + __c3 * __t554);
        let __dtau2_dq3 = (2159.0 / 5000.0)
            * (__c3 * __t117 + __s3 * __t545 + __t2 * __t119 + __c3 * __t555) - __t571;
        let __dtau2_dq4 = (2159.0 / 5000.0) * (__s3 * __t521 + __c3 * __t495) - __t572;
        let __dtau2_dq5 = (2159.0 / 5000.0) * (__s3 * __t522 + __c3 * __t485) - __t573;
        let __dtau2_dq6 = (2159.0 / 5000.0) * (__s3 * __t523 + __c3 * __t486) - __t574;
        let __dtau2_dqd1 = (-(1819.0 / 5000.0)) * __t316 - (3.0 / 500.0) * __t313
            - __t575 + (2159.0 / 5000.0) * (__t316 + __s3 * __t546 + __c3 * __t556);
        let __dtau2_dqd2 = (-(1819.0 / 5000.0)) * __t317 - (3.0 / 500.0) * __t314
            - __t576 + (2159.0 / 5000.0) * (__t317 + __s3 * __t547 + __c3 * __t557);
        let __dtau2_dqd3 = (2159.0 / 5000.0) * (__s3 * __t548 + __c3 * __t558) - __t577;
        let __dtau2_dqd4 = (2159.0 / 5000.0) * (__s3 * __t524 + __c3 * __t487) - __t578;
        let __dtau2_dqd5 = (2159.0 / 5000.0) * (__s3 * __t525 + __c3 * __t488) - __t579;
        let __dtau2_dqd6 = (2159.0 / 5000.0) * (__s3 * __t526 + __c3 * __t484) - __t580;
        let __dtau1_dq2 = __c2
            * ((3.0 / 500.0) * __t75
                - (91.0 / 400.0) * (87.0 / 5.0)
                    * (__t18 + __qd2 * __t70 - __t7 * __t73
                        + (-(1819.0 / 5000.0)) * __qdd2 - (91.0 / 400.0) * __t11)
                + __t122 + __t123)
            + __s2
                * ((3.0 / 500.0) * __t318 - (91.0 / 400.0) * __t315 + __c3 * __t559
                    + __t2 * __t581)
            + __t1
                * ((91.0 / 400.0) * (87.0 / 5.0)
                    * (__t17 + __t74 - __qd2 * __t72 + (91.0 / 400.0) * __t12
                        - (3.0 / 500.0) * __qdd2) - (-(1819.0 / 5000.0)) * __t75
                    + __s3 * __t120 + __c3 * __t121
                    - (2159.0 / 5000.0) * (__t75 - __t118))
            + __c2
                * ((91.0 / 400.0) * __t312 - (-(1819.0 / 5000.0)) * __t318
                    + __s3 * __t559 + __c3 * __t581
                    - (2159.0 / 5000.0) * (__t318 - __t549));
        let __dtau1_dq3 = __s2
            * (__t2 * __t120 + __c3 * __t560 + __t121 * __t124 + __t2 * __t582)
            + __c2
                * (__t122 + __s3 * __t560 + __t123 + __c3 * __t582
                    - (2159.0 / 5000.0) * (-__t550));
        let __dtau1_dq4 = __s2 * (__c3 * __t561 + __t2 * __t583)
            + __c2 * (__s3 * __t561 + __c3 * __t583 - (2159.0 / 5000.0) * (-__t527));
        let __dtau1_dq5 = __s2 * (__c3 * __t562 + __t2 * __t584)
            + __c2 * (__s3 * __t562 + __c3 * __t584 - (2159.0 / 5000.0) * (-__t528));
        let __dtau1_dq6 = __s2 * (__c3 * __t563 + __t2 * __t585)
            + __c2 * (__s3 * __t563 + __c3 * __t585 - (2159.0 / 5000.0) * (-__t529));
        let __dtau1_dqd1 = __s2
            * ((3.0 / 500.0) * __t319 - (91.0 / 400.0) * __t316 + __c3 * __t564
                + __t2 * __t586)
            + __c2
                * ((91.0 / 400.0) * __t313 - (-(1819.0 / 5000.0)) * __t319
                    + __s3 * __t564 + __c3 * __t586
                    - (2159.0 / 5000.0) * (__t319 - __t551));
        let __dtau1_dqd2 = __s2
            * ((3.0 / 500.0) * __t320 - (91.0 / 400.0) * __t317 + __c3 * __t565
                + __t2 * __t587)
            + __c2
                * ((91.0 / 400.0) * __t314 - (-(1819.0 / 5000.0)) * __t320
                    + __s3 * __t565 + __c3 * __t587
                    - (2159.0 / 5000.0) * (__t320 - __t552));
        let __dtau1_dqd3 = __s2 * (__c3 * __t566 + __t2 * __t588)
            + __c2 * (__s3 * __t566 + __c3 * __t588 - (2159.0 / 5000.0) * (-__t553));
        let __dtau1_dqd4 = __s2 * (__c3 * __t567 + __t2 * __t589)
            + __c2 * (__s3 * __t567 + __c3 * __t589 - (2159.0 / 5000.0) * (-__t530));
        let __dtau1_dqd5 = __s2 * (__c3 * __t568 + __t2 * __t590)
            + __c2 * (__s3 * __t568 + __c3 * __t590 - (2159.0 / 5000.0) * (-__t531));
        let __dtau1_dqd6 = __s2 * (__c3 * __t569 + __t2 * __t591)
            + __c2 * (__s3 * __t569 + __c3 * __t591 - (2159.0 / 5000.0) * (-__t532));
        let __dtau1_dq1 = 0.0;
        (
            ::planar_arm::__private::columns([
                [
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dq2,
                    __dtau2_dq2,
                    __dtau3_dq2,
                    __dtau4_dq2,
                    __dtau5_dq2,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dq3,
                    __dtau2_dq3,
                    __dtau3_dq3,
                    __dtau4_dq3,
                    __dtau5_dq3,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dq4,
                    __dtau2_dq4,
                    __dtau3_dq4,
                    __dtau4_dq4,
                    __dtau5_dq4,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dq5,
                    __dtau2_dq5,
                    __dtau3_dq5,
                    __dtau4_dq5,
                    __dtau5_dq5,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dq6,
                    __dtau2_dq6,
                    __dtau3_dq6,
                    __dtau4_dq6,
                    __dtau5_dq6,
                    __dtau1_dq1,
                ],
            ]),
            ::planar_arm::__private::columns([
                [
                    __dtau1_dqd1,
                    __dtau2_dqd1,
                    __dtau3_dqd1,
                    __dtau4_dqd1,
                    __dtau5_dqd1,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dqd2,
                    __dtau2_dqd2,
                    __dtau3_dqd2,
                    __dtau4_dqd2,
                    __dtau5_dqd2,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dqd3,
                    __dtau2_dqd3,
                    __dtau3_dqd3,
                    __dtau4_dqd3,
                    __dtau5_dqd3,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dqd4,
                    __dtau2_dqd4,
                    __dtau3_dqd4,
                    __dtau4_dqd4,
                    __dtau5_dqd4,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dqd5,
                    __dtau2_dqd5,
                    __dtau3_dqd5,
                    __dtau4_dqd5,
                    __dtau5_dqd5,
                    __dtau1_dq1,
                ],
                [
                    __dtau1_dqd6,
                    __dtau2_dqd6,
                    __dtau3_dqd6,
                    __dtau4_dqd6,
                    __dtau5_dqd6,
                    __dtau1_dq1,
                ],
            ]),
        )
    }
    #[doc(hidden)]
    #[inline(always)]
    fn __inverse_dynamics_derivatives_packed<__L: ::planar_arm::__private::Lanes>(
        &self,
        __lanes: __L,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
    ) {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [__qdd1, __qdd2, __qdd3, __qdd4, __qdd5, _] = ::planar_arm::__private::unpack(
            __qdd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __v17 = -__s3;
        let __v31 = -__s4;
        let __v42 = -__s5;
        let __v46 = -__s6;
        let __v13 = __s2 * __qd1;
        let __v12 = __c2 * __qd1;
        let __v18 = __s2 * __qdd1 + __qd2 * __v12;
        let __v19 = __c2 * __qdd1 - __qd2 * __v13;
        let __v14 = (2159.0 / 5000.0) * __qd2;
        let __v11 = -((2159.0 / 5000.0) * __v12);
        let __t1 = __v13 * __v14 - (2159.0 / 5000.0) * __v19;
        let __v15 = (981.0 / 100.0) * __s2 + __v12 * __v11 - __qd2 * __v14;
        let __v16 = (981.0 / 100.0) * __c2 + (2159.0 / 5000.0) * __qdd2 - __v13 * __v11;
        let __v28 = __c3 * __v13 + __s3 * __v12;
        let __v25 = __v17 * __v13 + __c3 * __v12;
        let __v20 = -__qd3;
        let __v23 = -__qd2 - __qd3;
        let __v33 = -__qdd2 - __qdd3;
        let __v32 = __c3 * __v18 + __s3 * __v19 - __v25 * __v20;
        let __t2 = __v17 * __v18 + __c3 * __v19 + __v28 * __v20;
        let __v26 = -((-(3001.0 / 20000.0)) * __v25);
        let __v24 = (203.0 / 10000.0) * __v25;
        let __v27 = (-(3001.0 / 20000.0)) * __v28 - (203.0 / 10000.0) * __v23;
        let __v29 = __c3 * __v15 + __s3 * __v16 + __v23 * __v27 - __v25 * __v24
            - (-(3001.0 / 20000.0)) * __t2;
        let __v30 = __v25 * __v26 - __v28 * __v27 + (203.0 / 10000.0) * __t2 - __t1;
        let __t3 = __v17 * __v15 + __c3 * __v16 + __v28 * __v24 - __v23 * __v26
            + (-(3001.0 / 20000.0)) * __v32 - (203.0 / 10000.0) * __v33;
        let __v39 = __c4 * __v28 + __s4 * __v23;
        let __t4 = __v31 * __v28 + __c4 * __v23;
        let __v38 = -__t4;
        let __v36 = __v25 + __qd4;
        let __v87 = __t2 + __qdd4;
        let __v86 = __c4 * __v32 + __s4 * __v33 - __qd4 * __v38;
        let __t5 = __qd4 * __v39 - (__v31 * __v32 + __c4 * __v33);
        let __v37 = -((2159.0 / 5000.0) * __v38);
        let __v35 = (2159.0 / 5000.0) * __v39;
        let __v84 = __c4 * __v29 + __s4 * __v30 + __v36 * __v35
            - (2159.0 / 5000.0) * __t5;
        let __v85 = __t3 + __v38 * __v37 - __v39 * __v35;
        let __t6 = (2159.0 / 5000.0) * __v86 - __v36 * __v37
            - (__v31 * __v29 + __c4 * __v30);
        let __v89 = __c5 * __v84 + __s5 * __v85;
        let __t7 = __v42 * __v84 + __c5 * __v85;
        let __v90 = -__t6;
        let __v91 = __c5 * __v39 + __s5 * __v36;
        let __v88 = __v42 * __v39 + __c5 * __v36;
        let __v43 = -__qd5;
        let __v92 = __t4 - __qd5;
        let __v94 = -__t5 - __qdd5;
        let __v93 = __c5 * __v86 + __s5 * __v87 - __v88 * __v43;
        let __v71 = __c6 * __v91 + __s6 * __v92;
        let __v72 = __v46 * __v91 + __c6 * __v92;
        let __v69 = __v88 + __qd6;
        let __v53 = (91.0 / 400.0) * __v12 - (3.0 / 500.0) * __qd2;
        let __v52 = (-(1819.0 / 5000.0)) * __qd2 - (91.0 / 400.0) * __v13;
        let __v51 = (3.0 / 500.0) * __v13 - (-(1819.0 / 5000.0)) * __v12;
        let __t8 = (87.0 / 5.0)
            * (__t1 + __v13 * __v52 - __v12 * __v53 + (3.0 / 500.0) * __v18
                - (-(1819.0 / 5000.0)) * __v19);
        let __v59 = (7.0 / 100.0) * __v23 - (-(141.0 / 10000.0)) * __v25;
        let __v58 = (-(203.0 / 10000.0)) * __v25 - (7.0 / 100.0) * __v28;
        let __v60 = (-(141.0 / 10000.0)) * __v28 - (-(203.0 / 10000.0)) * __v23;
        let __t9 = (24.0 / 5.0)
            * (__v29 + __v23 * __v60 - __v25 * __v58 + (7.0 / 100.0) * __v33
                - (-(141.0 / 10000.0)) * __t2);
        let __t10 = (24.0 / 5.0)
            * (__v30 + __v25 * __v59 - __v28 * __v60 + (-(203.0 / 10000.0)) * __t2
                - (7.0 / 100.0) * __v32);
        let __t11 = (24.0 / 5.0)
            * (__t3 + __v28 * __v58 - __v23 * __v59 + (-(141.0 / 10000.0)) * __v32
                - (-(203.0 / 10000.0)) * __v33);
        let __v64 = -((19.0 / 1000.0) * __v38);
        let __v63 = (19.0 / 1000.0) * __v39;
        let __t12 = (41.0 / 50.0) * (__v84 + __v36 * __v63 - (19.0 / 1000.0) * __t5);
        let __t13 = (41.0 / 50.0) * (__t6 + (19.0 / 1000.0) * __v86 - __v36 * __v64);
        let __v70 = (4.0 / 125.0) * __v72;
        let __v68 = -((4.0 / 125.0) * __v71);
        let __v95 = (9.0 / 100.0)
            * (__c6 * __v89 + __s6 * __v90
                + (4.0 / 125.0) * (__v46 * __v93 + __c6 * __v94 - __qd6 * __v71)
                - __v69 * __v68);
        let __v96 = (9.0 / 100.0)
            * (__v46 * __v89 + __c6 * __v90 + __v69 * __v70
                - (4.0 / 125.0) * (__c6 * __v93 + __s6 * __v94 + __qd6 * __v72));
        let __v97 = -((4.0 / 125.0) * __v96);
        let __v98 = (4.0 / 125.0) * __v95;
        let __v101 = __c6 * __v97 + __v46 * __v98;
        let __v99 = (17.0 / 50.0) * __v89 + __c6 * __v95 + __v46 * __v96;
        let __v100 = (17.0 / 50.0) * __t7
            + (9.0 / 100.0) * (__t7 + __v71 * __v68 - __v72 * __v70);
        let __v74 = __t12 + __c5 * __v99 + __v42 * __v100;
        let __t14 = __t13 - ((17.0 / 50.0) * __v90 + __s6 * __v95 + __c6 * __v96);
        let __v76 = (19.0 / 1000.0) * __t13 + __c5 * __v101 + (2159.0 / 5000.0) * __t14;
        let __v75 = -__t14;
        let __v77 = -(-((19.0 / 1000.0) * __t12) - (__s6 * __v97 + __c6 * __v98)
            - (2159.0 / 5000.0) * __v74);
        let __v78 = __t9 + __c4 * __v74 + __v31 * __v75;
        let __t15 = __t10 + __s4 * __v74 + __c4 * __v75;
        let __v79 = __t11 + (41.0 / 50.0) * (__v85 + __v38 * __v64 - __v39 * __v63)
            + __s5 * __v99 + __c5 * __v100;
        let __v80 = (-(141.0 / 10000.0)) * __t11 - (7.0 / 100.0) * __t10 + __c4 * __v76
            + __v31 * __v77 + (-(3001.0 / 20000.0)) * __v79;
        let __v81 = (-(203.0 / 10000.0)) * __t10 - (-(141.0 / 10000.0)) * __t9
            + __s5 * __v101 + (203.0 / 10000.0) * __t15 - (-(3001.0 / 20000.0)) * __v78;
        let __v82 = (3.0 / 500.0) * __t8
            - (91.0 / 400.0) * (87.0 / 5.0)
                * (__v16 + __qd2 * __v53 - __v13 * __v51 + (-(1819.0 / 5000.0)) * __qdd2
                    - (91.0 / 400.0) * __v18) + __c3 * __v80 + __v17 * __v81;
        let __v83 = (91.0 / 400.0) * (87.0 / 5.0)
            * (__v15 + __v12 * __v51 - __qd2 * __v52 + (91.0 / 400.0) * __v19
                - (3.0 / 500.0) * __qdd2) - (-(1819.0 / 5000.0)) * __t8 + __s3 * __v80
            + __c3 * __v81 - (2159.0 / 5000.0) * (__t8 - __t15);
        let __v6 = (981.0 / 100.0);
        let __v10 = (2159.0 / 5000.0);
        let __v21 = (-(3001.0 / 20000.0));
        let __v22 = (203.0 / 10000.0);
        let __v48 = (91.0 / 400.0);
        let __v49 = (3.0 / 500.0);
        let __v50 = (-(1819.0 / 5000.0));
        let __v54 = (87.0 / 5.0);
        let __v55 = (-(141.0 / 10000.0));
        let __v56 = (-(203.0 / 10000.0));
        let __v57 = (7.0 / 100.0);
        let __v61 = (24.0 / 5.0);
        let __v62 = (19.0 / 1000.0);
        let __v65 = (41.0 / 50.0);
        let __v66 = (17.0 / 50.0);
        let __v67 = (4.0 / 125.0);
        let __v73 = (9.0 / 100.0);
        let __lane0 = __lanes.constant([0.0, -1.0, 0.0, 0.0]);
        let __lane1 = __lanes.mul(__lane0, __lanes.splat(__s2));
        let __lane2 = __lanes.constant([0.0, 1.0, 0.0, 0.0]);
        let __lane3 = __lanes.mul(__lane2, __lanes.splat(__c2));
        let __lane4 = __lanes.constant([0.0, 0.0, -1.0, 0.0]);
        let __lane5 = __lanes.mul(__lane4, __lanes.splat(__s3));
        let __lane6 = __lanes.constant([0.0, 0.0, 1.0, 0.0]);
        let __lane7 = __lanes.mul(__lane6, __lanes.splat(__c3));
        let __lane8 = __lanes.neg(__lane7);
        let __lane9 = __lanes.constant([0.0, 0.0, 0.0, -1.0]);
        let __lane10 = __lanes.mul(__lane9, __lanes.splat(__s4));
        let __lane11 = __lanes.constant([0.0, 0.0, 0.0, 1.0]);
        let __lane12 = __lanes.mul(__lane11, __lanes.splat(__c4));
        let __lane13 = __lanes.neg(__lane12);
        let __lane16 = __lanes.mul(__lane3, __lanes.splat(__qd1));
        let __lane17 = __lanes.mul(__lane1, __lanes.splat(__qd1));
        let __lane18 = __lanes.mul(__lane3, __lanes.splat(__qdd1));
        let __lane19 = __lanes.mul(__lane1, __lanes.splat(__qdd1));
        let __lane22 = __lanes.mul_add(__lane17, __qd2, __lane18);
        let __lane23 = __lanes.neg_mul_add(__lane16, __qd2, __lane19);
        let __lane24 = __lanes.mul(__lane17, __lanes.splat(__v10));
        let __lane25 = __lanes.neg(__lane24);
        let __lane26 = __lanes.mul(__lane17, __lanes.splat(__v11));
        let __lane28 = __lanes.mul_add(__lane25, __v12, __lane26);
        let __lane29 = __lanes.mul(__lane16, __lanes.splat(__v11));
        let __lane31 = __lanes.mul_add(__lane25, __v13, __lane29);
        let __lane32 = __lanes.mul(__lane16, __lanes.splat(__v14));
        let __lane34 = __lanes.neg(__lane31);
        let __lane35 = __lanes.neg_mul_add(__lane23, __v10, __lane32);
        let __lane36 = __lanes.mul_add(__lane3, __v6, __lane28);
        let __lane37 = __lanes.mul_add(__lane1, __v6, __lane34);
        let __lane38 = __lanes.mul(__lane5, __lanes.splat(__v15));
        let __lane40 = __lanes.mul_add(__lane36, __c3, __lane38);
        let __lane41 = __lanes.mul(__lane7, __lanes.splat(__v16));
        let __lane43 = __lanes.mul_add(__lane37, __s3, __lane41);
        let __lane44 = __lanes.add(__lane40, __lane43);
        let __lane45 = __lanes.mul(__lane8, __lanes.splat(__v15));
        let __lane47 = __lanes.mul_add(__lane36, __v17, __lane45);
        let __lane48 = __lanes.mul(__lane5, __lanes.splat(__v16));
        let __lane50 = __lanes.mul_add(__lane37, __c3, __lane48);
        let __lane51 = __lanes.add(__lane47, __lane50);
        let __lane52 = __lanes.mul(__lane5, __lanes.splat(__v13));
        let __lane54 = __lanes.mul_add(__lane16, __c3, __lane52);
        let __lane55 = __lanes.mul(__lane7, __lanes.splat(__v12));
        let __lane57 = __lanes.mul_add(__lane17, __s3, __lane55);
        let __lane58 = __lanes.add(__lane54, __lane57);
        let __lane59 = __lanes.mul(__lane8, __lanes.splat(__v13));
        let __lane61 = __lanes.mul_add(__lane16, __v17, __lane59);
        let __lane62 = __lanes.mul(__lane5, __lanes.splat(__v12));
        let __lane64 = __lanes.mul_add(__lane17, __c3, __lane62);
        let __lane65 = __lanes.add(__lane61, __lane64);
        let __lane66 = __lanes.mul(__lane5, __lanes.splat(__v18));
        let __lane68 = __lanes.mul_add(__lane22, __c3, __lane66);
        let __lane69 = __lanes.mul(__lane7, __lanes.splat(__v19));
        let __lane71 = __lanes.mul_add(__lane23, __s3, __lane69);
        let __lane72 = __lanes.add(__lane68, __lane71);
        let __lane73 = __lanes.mul(__lane8, __lanes.splat(__v18));
        let __lane75 = __lanes.mul_add(__lane22, __v17, __lane73);
        let __lane76 = __lanes.mul(__lane5, __lanes.splat(__v19));
        let __lane78 = __lanes.mul_add(__lane23, __c3, __lane76);
        let __lane79 = __lanes.add(__lane75, __lane78);
        let __lane82 = __lanes.neg_mul_add(__lane65, __v20, __lane72);
        let __lane83 = __lanes.mul_add(__lane58, __v20, __lane79);
        let __lane84 = __lanes.mul(__lane65, __lanes.splat(__v21));
        let __lane85 = __lanes.neg(__lane84);
        let __lane86 = __lanes.mul(__lane65, __lanes.splat(__v22));
        let __lane87 = __lanes.mul(__lane58, __lanes.splat(__v21));
        let __lane89 = __lanes.mul(__lane65, __lanes.splat(__v24));
        let __lane91 = __lanes.mul_add(__lane86, __v25, __lane89);
        let __lane92 = __lanes.mul_sub(__lane87, __v23, __lane91);
        let __lane93 = __lanes.mul(__lane65, __lanes.splat(__v26));
        let __lane95 = __lanes.mul_add(__lane85, __v25, __lane93);
        let __lane96 = __lanes.mul(__lane58, __lanes.splat(__v27));
        let __lane98 = __lanes.mul_add(__lane87, __v28, __lane96);
        let __lane99 = __lanes.sub(__lane95, __lane98);
        let __lane100 = __lanes.mul(__lane58, __lanes.splat(__v24));
        let __lane102 = __lanes.mul_add(__lane86, __v28, __lane100);
        let __lane104 = __lanes.neg_mul_add(__lane85, __v23, __lane102);
        let __lane108 = __lanes.neg_mul_add(__lane83, __v21, __lane92);
        let __lane109 = __lanes.mul_add(__lane83, __v22, __lane99);
        let __lane110 = __lanes.mul_add(__lane82, __v21, __lane104);
        let __lane111 = __lanes.add(__lane44, __lane108);
        let __lane112 = __lanes.sub(__lane109, __lane35);
        let __lane113 = __lanes.add(__lane51, __lane110);
        let __lane114 = __lanes.mul(__lane10, __lanes.splat(__v29));
        let __lane116 = __lanes.mul_add(__lane111, __c4, __lane114);
        let __lane117 = __lanes.mul(__lane12, __lanes.splat(__v30));
        let __lane119 = __lanes.mul_add(__lane112, __s4, __lane117);
        let __lane120 = __lanes.add(__lane116, __lane119);
        let __lane121 = __lanes.mul(__lane13, __lanes.splat(__v29));
        let __lane123 = __lanes.mul_add(__lane111, __v31, __lane121);
        let __lane124 = __lanes.mul(__lane10, __lanes.splat(__v30));
        let __lane126 = __lanes.mul_add(__lane112, __c4, __lane124);
        let __lane127 = __lanes.add(__lane123, __lane126);
        let __lane128 = __lanes.mul(__lane10, __lanes.splat(__v28));
        let __lane130 = __lanes.mul_add(__lane58, __c4, __lane128);
        let __lane132 = __lanes.mul_add(__lane12, __v23, __lane130);
        let __lane133 = __lanes.mul(__lane13, __lanes.splat(__v28));
        let __lane135 = __lanes.mul_add(__lane58, __v31, __lane133);
        let __lane137 = __lanes.mul_add(__lane10, __v23, __lane135);
        let __lane138 = __lanes.neg(__lane137);
        let __lane139 = __lanes.mul(__lane10, __lanes.splat(__v32));
        let __lane141 = __lanes.mul_add(__lane82, __c4, __lane139);
        let __lane143 = __lanes.mul_add(__lane12, __v33, __lane141);
        let __lane144 = __lanes.mul(__lane13, __lanes.splat(__v32));
        let __lane146 = __lanes.mul_add(__lane82, __v31, __lane144);
        let __lane148 = __lanes.mul_add(__lane10, __v33, __lane146);
        let __lane151 = __lanes.neg_mul_add(__lane138, __qd4, __lane143);
        let __lane152 = __lanes.mul_sub(__lane132, __qd4, __lane148);
        let __lane153 = __lanes.mul(__lane138, __lanes.splat(__v10));
        let __lane154 = __lanes.neg(__lane153);
        let __lane155 = __lanes.mul(__lane132, __lanes.splat(__v10));
        let __lane156 = __lanes.mul(__lane65, __lanes.splat(__v35));
        let __lane158 = __lanes.mul_add(__lane155, __v36, __lane156);
        let __lane159 = __lanes.mul(__lane138, __lanes.splat(__v37));
        let __lane161 = __lanes.mul_add(__lane154, __v38, __lane159);
        let __lane162 = __lanes.mul(__lane132, __lanes.splat(__v35));
        let __lane164 = __lanes.mul_add(__lane155, __v39, __lane162);
        let __lane165 = __lanes.sub(__lane161, __lane164);
        let __lane166 = __lanes.mul(__lane65, __lanes.splat(__v37));
        let __lane168 = __lanes.mul_add(__lane154, __v36, __lane166);
        let __lane171 = __lanes.neg_mul_add(__lane152, __v10, __lane158);
        let __lane172 = __lanes.mul_sub(__lane151, __v10, __lane168);
        let __lane173 = __lanes.add(__lane120, __lane171);
        let __lane174 = __lanes.add(__lane113, __lane165);
        let __lane175 = __lanes.sub(__lane172, __lane127);
        let __lane176 = __lanes.mul(__lane173, __lanes.splat(__c5));
        let __lane178 = __lanes.mul_add(__lane174, __s5, __lane176);
        let __lane179 = __lanes.mul(__lane173, __lanes.splat(__v42));
        let __lane181 = __lanes.mul_add(__lane174, __c5, __lane179);
        let __lane182 = __lanes.neg(__lane175);
        let __lane183 = __lanes.mul(__lane132, __lanes.splat(__c5));
        let __lane185 = __lanes.mul_add(__lane65, __s5, __lane183);
        let __lane186 = __lanes.mul(__lane132, __lanes.splat(__v42));
        let __lane188 = __lanes.mul_add(__lane65, __c5, __lane186);
        let __lane189 = __lanes.mul(__lane151, __lanes.splat(__c5));
        let __lane191 = __lanes.mul_add(__lane83, __s5, __lane189);
        let __lane192 = __lanes.neg(__lane152);
        let __lane194 = __lanes.neg_mul_add(__lane188, __v43, __lane191);
        let __lane195 = __lanes.mul(__lane178, __lanes.splat(__c6));
        let __lane197 = __lanes.mul_add(__lane182, __s6, __lane195);
        let __lane198 = __lanes.mul(__lane178, __lanes.splat(__v46));
        let __lane200 = __lanes.mul_add(__lane182, __c6, __lane198);
        let __lane201 = __lanes.mul(__lane185, __lanes.splat(__c6));
        let __lane203 = __lanes.mul_add(__lane137, __s6, __lane201);
        let __lane204 = __lanes.mul(__lane185, __lanes.splat(__v46));
        let __lane206 = __lanes.mul_add(__lane137, __c6, __lane204);
        let __lane207 = __lanes.mul(__lane194, __lanes.splat(__c6));
        let __lane209 = __lanes.mul_add(__lane192, __s6, __lane207);
        let __lane210 = __lanes.mul(__lane194, __lanes.splat(__v46));
        let __lane212 = __lanes.mul_add(__lane192, __c6, __lane210);
        let __lane215 = __lanes.mul_add(__lane206, __qd6, __lane209);
        let __lane216 = __lanes.neg_mul_add(__lane203, __qd6, __lane212);
        let __lane217 = __lanes.mul(__lane17, __lanes.splat(__v48));
        let __lane218 = __lanes.mul(__lane16, __lanes.splat(__v48));
        let __lane219 = __lanes.neg(__lane218);
        let __lane220 = __lanes.mul(__lane16, __lanes.splat(__v49));
        let __lane222 = __lanes.neg_mul_add(__lane17, __v50, __lane220);
        let __lane223 = __lanes.mul(__lane17, __lanes.splat(__v51));
        let __lane225 = __lanes.mul_add(__lane222, __v12, __lane223);
        let __lane227 = __lanes.neg_mul_add(__lane219, __qd2, __lane225);
        let __lane229 = __lanes.mul(__lane16, __lanes.splat(__v51));
        let __lane231 = __lanes.mul_add(__lane222, __v13, __lane229);
        let __lane232 = __lanes.mul_sub(__lane217, __qd2, __lane231);
        let __lane233 = __lanes.mul(__lane16, __lanes.splat(__v52));
        let __lane235 = __lanes.mul_add(__lane219, __v13, __lane233);
        let __lane236 = __lanes.mul(__lane17, __lanes.splat(__v53));
        let __lane238 = __lanes.mul_add(__lane217, __v12, __lane236);
        let __lane239 = __lanes.sub(__lane235, __lane238);
        let __lane241 = __lanes.mul(__lane22, __lanes.splat(__v48));
        let __lane242 = __lanes.neg(__lane241);
        let __lane243 = __lanes.mul(__lane22, __lanes.splat(__v49));
        let __lane245 = __lanes.neg_mul_add(__lane23, __v50, __lane243);
        let __lane246 = __lanes.mul_add(__lane23, __v48, __lane227);
        let __lane247 = __lanes.add(__lane232, __lane242);
        let __lane248 = __lanes.add(__lane239, __lane245);
        let __lane249 = __lanes.add(__lane36, __lane246);
        let __lane250 = __lanes.add(__lane37, __lane247);
        let __lane251 = __lanes.add(__lane35, __lane248);
        let __lane252 = __lanes.mul(__lane249, __lanes.splat(__v54));
        let __lane253 = __lanes.mul(__lane250, __lanes.splat(__v54));
        let __lane254 = __lanes.mul(__lane251, __lanes.splat(__v54));
        let __lane255 = __lanes.mul(__lane254, __lanes.splat(__v49));
        let __lane257 = __lanes.neg_mul_add(__lane253, __v48, __lane255);
        let __lane258 = __lanes.mul(__lane252, __lanes.splat(__v48));
        let __lane260 = __lanes.neg_mul_add(__lane254, __v50, __lane258);
        let __lane261 = __lanes.mul(__lane253, __lanes.splat(__v50));
        let __lane263 = __lanes.neg_mul_add(__lane252, __v49, __lane261);
        let __lane264 = __lanes.mul(__lane65, __lanes.splat(__v55));
        let __lane265 = __lanes.neg(__lane264);
        let __lane266 = __lanes.mul(__lane65, __lanes.splat(__v56));
        let __lane268 = __lanes.neg_mul_add(__lane58, __v57, __lane266);
        let __lane269 = __lanes.mul(__lane58, __lanes.splat(__v55));
        let __lane271 = __lanes.mul(__lane65, __lanes.splat(__v58));
        let __lane273 = __lanes.mul_add(__lane268, __v25, __lane271);
        let __lane274 = __lanes.mul_sub(__lane269, __v23, __lane273);
        let __lane275 = __lanes.mul(__lane65, __lanes.splat(__v59));
        let __lane277 = __lanes.mul_add(__lane265, __v25, __lane275);
        let __lane278 = __lanes.mul(__lane58, __lanes.splat(__v60));
        let __lane280 = __lanes.mul_add(__lane269, __v28, __lane278);
        let __lane281 = __lanes.sub(__lane277, __lane280);
        let __lane282 = __lanes.mul(__lane58, __lanes.splat(__v58));
        let __lane284 = __lanes.mul_add(__lane268, __v28, __lane282);
        let __lane286 = __lanes.neg_mul_add(__lane265, __v23, __lane284);
        let __lane287 = __lanes.mul(__lane83, __lanes.splat(__v55));
        let __lane288 = __lanes.neg(__lane287);
        let __lane289 = __lanes.mul(__lane83, __lanes.splat(__v56));
        let __lane291 = __lanes.neg_mul_add(__lane82, __v57, __lane289);
        let __lane293 = __lanes.add(__lane274, __lane288);
        let __lane294 = __lanes.add(__lane281, __lane291);
        let __lane295 = __lanes.mul_add(__lane82, __v55, __lane286);
        let __lane296 = __lanes.add(__lane111, __lane293);
        let __lane297 = __lanes.add(__lane112, __lane294);
        let __lane298 = __lanes.add(__lane113, __lane295);
        let __lane299 = __lanes.mul(__lane296, __lanes.splat(__v61));
        let __lane300 = __lanes.mul(__lane297, __lanes.splat(__v61));
        let __lane301 = __lanes.mul(__lane298, __lanes.splat(__v61));
        let __lane302 = __lanes.mul(__lane301, __lanes.splat(__v55));
        let __lane304 = __lanes.neg_mul_add(__lane300, __v57, __lane302);
        let __lane305 = __lanes.mul(__lane299, __lanes.splat(__v57));
        let __lane307 = __lanes.neg_mul_add(__lane301, __v56, __lane305);
        let __lane308 = __lanes.mul(__lane300, __lanes.splat(__v56));
        let __lane310 = __lanes.neg_mul_add(__lane299, __v55, __lane308);
        let __lane311 = __lanes.mul(__lane138, __lanes.splat(__v62));
        let __lane312 = __lanes.neg(__lane311);
        let __lane313 = __lanes.mul(__lane132, __lanes.splat(__v62));
        let __lane314 = __lanes.mul(__lane65, __lanes.splat(__v63));
        let __lane316 = __lanes.mul_add(__lane313, __v36, __lane314);
        let __lane317 = __lanes.mul(__lane138, __lanes.splat(__v64));
        let __lane319 = __lanes.mul_add(__lane312, __v38, __lane317);
        let __lane320 = __lanes.mul(__lane132, __lanes.splat(__v63));
        let __lane322 = __lanes.mul_add(__lane313, __v39, __lane320);
        let __lane323 = __lanes.sub(__lane319, __lane322);
        let __lane324 = __lanes.mul(__lane65, __lanes.splat(__v64));
        let __lane326 = __lanes.mul_add(__lane312, __v36, __lane324);
        let __lane329 = __lanes.neg_mul_add(__lane152, __v62, __lane316);
        let __lane330 = __lanes.mul_sub(__lane151, __v62, __lane326);
        let __lane331 = __lanes.add(__lane173, __lane329);
        let __lane332 = __lanes.add(__lane174, __lane323);
        let __lane333 = __lanes.add(__lane175, __lane330);
        let __lane334 = __lanes.mul(__lane331, __lanes.splat(__v65));
        let __lane336 = __lanes.mul(__lane333, __lanes.splat(__v65));
        let __lane337 = __lanes.mul(__lane336, __lanes.splat(__v62));
        let __lane338 = __lanes.mul(__lane334, __lanes.splat(__v62));
        let __lane339 = __lanes.neg(__lane338);
        let __lane342 = __lanes.mul(__lane181, __lanes.splat(__v66));
        let __lane343 = __lanes.mul(__lane206, __lanes.splat(__v67));
        let __lane344 = __lanes.mul(__lane203, __lanes.splat(__v67));
        let __lane345 = __lanes.neg(__lane344);
        let __lane346 = __lanes.mul(__lane188, __lanes.splat(__v68));
        let __lane348 = __lanes.mul_add(__lane345, __v69, __lane346);
        let __lane349 = __lanes.mul(__lane188, __lanes.splat(__v70));
        let __lane351 = __lanes.mul_add(__lane343, __v69, __lane349);
        let __lane352 = __lanes.mul(__lane203, __lanes.splat(__v68));
        let __lane354 = __lanes.mul_add(__lane345, __v71, __lane352);
        let __lane355 = __lanes.mul(__lane206, __lanes.splat(__v70));
        let __lane357 = __lanes.mul_add(__lane343, __v72, __lane355);
        let __lane358 = __lanes.sub(__lane354, __lane357);
        let __lane361 = __lanes.mul_sub(__lane216, __v67, __lane348);
        let __lane362 = __lanes.neg_mul_add(__lane215, __v67, __lane351);
        let __lane363 = __lanes.add(__lane197, __lane361);
        let __lane364 = __lanes.add(__lane200, __lane362);
        let __lane365 = __lanes.add(__lane181, __lane358);
        let __lane366 = __lanes.mul(__lane363, __lanes.splat(__v73));
        let __lane367 = __lanes.mul(__lane364, __lanes.splat(__v73));
        let __lane369 = __lanes.mul(__lane367, __lanes.splat(__v67));
        let __lane370 = __lanes.neg(__lane369);
        let __lane371 = __lanes.mul(__lane366, __lanes.splat(__v67));
        let __lane372 = __lanes.mul(__lane366, __lanes.splat(__c6));
        let __lane374 = __lanes.mul_add(__lane367, __v46, __lane372);
        let __lane375 = __lanes.mul(__lane366, __lanes.splat(__s6));
        let __lane377 = __lanes.mul_add(__lane367, __c6, __lane375);
        let __lane378 = __lanes.mul(__lane370, __lanes.splat(__c6));
        let __lane380 = __lanes.mul_add(__lane371, __v46, __lane378);
        let __lane381 = __lanes.mul(__lane370, __lanes.splat(__s6));
        let __lane383 = __lanes.mul_add(__lane371, __c6, __lane381);
        let __lane384 = __lanes.mul_add(__lane178, __v66, __lane374);
        let __lane385 = __lanes.mul_add(__lane182, __v66, __lane377);
        let __lane386 = __lanes.mul_add(__lane365, __v73, __lane342);
        let __lane387 = __lanes.neg(__lane383);
        let __lane388 = __lanes.mul(__lane384, __lanes.splat(__c5));
        let __lane390 = __lanes.mul_add(__lane386, __v42, __lane388);
        let __lane391 = __lanes.mul(__lane384, __lanes.splat(__s5));
        let __lane393 = __lanes.mul_add(__lane386, __c5, __lane391);
        let __lane395 = __lanes.mul(__lane380, __lanes.splat(__s5));
        let __lane396 = __lanes.add(__lane334, __lane390);
        let __lane397 = __lanes.mul_add(__lane332, __v65, __lane393);
        let __lane398 = __lanes.sub(__lane336, __lane385);
        let __lane399 = __lanes.mul_add(__lane380, __c5, __lane337);
        let __lane400 = __lanes.sub(__lane339, __lane383);
        let __lane403 = __lanes.mul_add(__lane398, __v10, __lane399);
        let __lane404 = __lanes.neg_mul_add(__lane396, __v10, __lane400);
        let __lane405 = __lanes.neg(__lane398);
        let __lane406 = __lanes.mul(__lane10, __lanes.splat(__v74));
        let __lane408 = __lanes.mul_add(__lane396, __c4, __lane406);
        let __lane409 = __lanes.mul(__lane13, __lanes.splat(__v75));
        let __lane411 = __lanes.mul_add(__lane405, __v31, __lane409);
        let __lane412 = __lanes.add(__lane408, __lane411);
        let __lane413 = __lanes.mul(__lane12, __lanes.splat(__v74));
        let __lane415 = __lanes.mul_add(__lane396, __s4, __lane413);
        let __lane416 = __lanes.mul(__lane10, __lanes.splat(__v75));
        let __lane418 = __lanes.mul_add(__lane405, __c4, __lane416);
        let __lane419 = __lanes.add(__lane415, __lane418);
        let __lane420 = __lanes.neg(__lane404);
        let __lane421 = __lanes.mul(__lane10, __lanes.splat(__v76));
        let __lane423 = __lanes.mul_add(__lane403, __c4, __lane421);
        let __lane424 = __lanes.mul(__lane13, __lanes.splat(__v77));
        let __lane426 = __lanes.mul_add(__lane420, __v31, __lane424);
        let __lane427 = __lanes.add(__lane423, __lane426);
        let __lane428 = __lanes.mul(__lane12, __lanes.splat(__v76));
        let __lane430 = __lanes.mul_add(__lane403, __s4, __lane428);
        let __lane431 = __lanes.mul(__lane10, __lanes.splat(__v77));
        let __lane433 = __lanes.mul_add(__lane420, __c4, __lane431);
        let __lane434 = __lanes.add(__lane430, __lane433);
        let __lane435 = __lanes.add(__lane299, __lane412);
        let __lane436 = __lanes.add(__lane300, __lane419);
        let __lane437 = __lanes.add(__lane301, __lane397);
        let __lane438 = __lanes.add(__lane304, __lane427);
        let __lane439 = __lanes.add(__lane307, __lane434);
        let __lane440 = __lanes.add(__lane310, __lane395);
        let __lane443 = __lanes.mul(__lane436, __lanes.splat(__v22));
        let __lane445 = __lanes.neg_mul_add(__lane435, __v21, __lane443);
        let __lane446 = __lanes.mul_add(__lane437, __v21, __lane438);
        let __lane447 = __lanes.neg_mul_add(__lane437, __v22, __lane439);
        let __lane448 = __lanes.add(__lane440, __lane445);
        let __lane449 = __lanes.neg(__lane447);
        let __lane450 = __lanes.mul(__lane7, __lanes.splat(__v78));
        let __lane452 = __lanes.mul_add(__lane435, __s3, __lane450);
        let __lane453 = __lanes.mul(__lane5, __lanes.splat(__v79));
        let __lane455 = __lanes.mul_add(__lane437, __c3, __lane453);
        let __lane456 = __lanes.add(__lane452, __lane455);
        let __lane457 = __lanes.mul(__lane5, __lanes.splat(__v80));
        let __lane459 = __lanes.mul_add(__lane446, __c3, __lane457);
        let __lane460 = __lanes.mul(__lane8, __lanes.splat(__v81));
        let __lane462 = __lanes.mul_add(__lane448, __v17, __lane460);
        let __lane463 = __lanes.add(__lane459, __lane462);
        let __lane464 = __lanes.mul(__lane7, __lanes.splat(__v80));
        let __lane466 = __lanes.mul_add(__lane446, __s3, __lane464);
        let __lane467 = __lanes.mul(__lane5, __lanes.splat(__v81));
        let __lane469 = __lanes.mul_add(__lane448, __c3, __lane467);
        let __lane470 = __lanes.add(__lane466, __lane469);
        let __lane471 = __lanes.add(__lane253, __lane456);
        let __lane472 = __lanes.sub(__lane254, __lane436);
        let __lane473 = __lanes.add(__lane257, __lane463);
        let __lane474 = __lanes.add(__lane260, __lane470);
        let __lane475 = __lanes.sub(__lane263, __lane447);
        let __lane478 = __lanes.neg_mul_add(__lane472, __v10, __lane474);
        let __lane479 = __lanes.mul_add(__lane471, __v10, __lane475);
        let __lane480 = __lanes.mul(__lane3, __lanes.splat(__v82));
        let __lane482 = __lanes.mul_add(__lane473, __s2, __lane480);
        let __lane483 = __lanes.mul(__lane1, __lanes.splat(__v83));
        let __lane485 = __lanes.mul_add(__lane478, __c2, __lane483);
        let __lane486 = __lanes.add(__lane482, __lane485);
        let __lane487 = __lanes.constant([1.0, 0.0, 0.0, 0.0]);
        let __lane488 = __lanes.mul(__lane487, __lanes.splat(__s2));
        let __lane489 = __lanes.mul(__lane487, __lanes.splat(__c2));
        let __lane490 = __lanes.mul(__lane2, __lanes.splat(__v12));
        let __lane492 = __lanes.mul_add(__lane489, __qd2, __lane490);
        let __lane493 = __lanes.mul(__lane2, __lanes.splat(__v13));
        let __lane495 = __lanes.mul_add(__lane488, __qd2, __lane493);
        let __lane496 = __lanes.neg(__lane495);
        let __lane497 = __lanes.mul(__lane2, __lanes.splat(__v10));
        let __lane498 = __lanes.mul(__lane489, __lanes.splat(__v10));
        let __lane499 = __lanes.neg(__lane498);
        let __lane500 = __lanes.mul(__lane489, __lanes.splat(__v11));
        let __lane502 = __lanes.mul_add(__lane499, __v12, __lane500);
        let __lane503 = __lanes.mul(__lane2, __lanes.splat(__v14));
        let __lane505 = __lanes.mul_add(__lane497, __qd2, __lane503);
        let __lane506 = __lanes.sub(__lane502, __lane505);
        let __lane507 = __lanes.mul(__lane488, __lanes.splat(__v11));
        let __lane509 = __lanes.mul_add(__lane499, __v13, __lane507);
        let __lane510 = __lanes.mul(__lane488, __lanes.splat(__v14));
        let __lane512 = __lanes.mul_add(__lane497, __v13, __lane510);
        let __lane514 = __lanes.neg(__lane509);
        let __lane515 = __lanes.neg_mul_add(__lane496, __v10, __lane512);
        let __lane516 = __lanes.mul(__lane506, __lanes.splat(__c3));
        let __lane518 = __lanes.mul_add(__lane514, __s3, __lane516);
        let __lane519 = __lanes.mul(__lane506, __lanes.splat(__v17));
        let __lane521 = __lanes.mul_add(__lane514, __c3, __lane519);
        let __lane522 = __lanes.mul(__lane488, __lanes.splat(__c3));
        let __lane524 = __lanes.mul_add(__lane489, __s3, __lane522);
        let __lane525 = __lanes.mul(__lane488, __lanes.splat(__v17));
        let __lane527 = __lanes.mul_add(__lane489, __c3, __lane525);
        let __lane528 = __lanes.neg(__lane2);
        let __lane529 = __lanes.mul(__lane492, __lanes.splat(__c3));
        let __lane531 = __lanes.mul_add(__lane496, __s3, __lane529);
        let __lane532 = __lanes.mul(__lane492, __lanes.splat(__v17));
        let __lane534 = __lanes.mul_add(__lane496, __c3, __lane532);
        let __lane535 = __lanes.neg(__lane6);
        let __lane536 = __lanes.sub(__lane528, __lane6);
        let __lane537 = __lanes.mul(__lane527, __lanes.splat(__v20));
        let __lane539 = __lanes.mul_add(__lane535, __v25, __lane537);
        let __lane540 = __lanes.mul(__lane524, __lanes.splat(__v20));
        let __lane542 = __lanes.mul_add(__lane535, __v28, __lane540);
        let __lane543 = __lanes.sub(__lane531, __lane539);
        let __lane544 = __lanes.add(__lane534, __lane542);
        let __lane545 = __lanes.mul(__lane527, __lanes.splat(__v21));
        let __lane546 = __lanes.neg(__lane545);
        let __lane547 = __lanes.mul(__lane527, __lanes.splat(__v22));
        let __lane548 = __lanes.mul(__lane524, __lanes.splat(__v21));
        let __lane550 = __lanes.neg_mul_add(__lane536, __v22, __lane548);
        let __lane551 = __lanes.mul(__lane536, __lanes.splat(__v27));
        let __lane553 = __lanes.mul_add(__lane550, __v23, __lane551);
        let __lane554 = __lanes.mul(__lane527, __lanes.splat(__v24));
        let __lane556 = __lanes.mul_add(__lane547, __v25, __lane554);
        let __lane557 = __lanes.sub(__lane553, __lane556);
        let __lane558 = __lanes.mul(__lane527, __lanes.splat(__v26));
        let __lane560 = __lanes.mul_add(__lane546, __v25, __lane558);
        let __lane561 = __lanes.mul(__lane524, __lanes.splat(__v27));
        let __lane563 = __lanes.mul_add(__lane550, __v28, __lane561);
        let __lane564 = __lanes.sub(__lane560, __lane563);
        let __lane565 = __lanes.mul(__lane524, __lanes.splat(__v24));
        let __lane567 = __lanes.mul_add(__lane547, __v28, __lane565);
        let __lane568 = __lanes.mul(__lane536, __lanes.splat(__v26));
        let __lane570 = __lanes.mul_add(__lane546, __v23, __lane568);
        let __lane571 = __lanes.sub(__lane567, __lane570);
        let __lane575 = __lanes.neg_mul_add(__lane544, __v21, __lane557);
        let __lane576 = __lanes.mul_add(__lane544, __v22, __lane564);
        let __lane577 = __lanes.mul_add(__lane543, __v21, __lane571);
        let __lane578 = __lanes.add(__lane518, __lane575);
        let __lane579 = __lanes.sub(__lane576, __lane515);
        let __lane580 = __lanes.add(__lane521, __lane577);
        let __lane581 = __lanes.mul(__lane578, __lanes.splat(__c4));
        let __lane583 = __lanes.mul_add(__lane579, __s4, __lane581);
        let __lane584 = __lanes.mul(__lane578, __lanes.splat(__v31));
        let __lane586 = __lanes.mul_add(__lane579, __c4, __lane584);
        let __lane587 = __lanes.mul(__lane524, __lanes.splat(__c4));
        let __lane589 = __lanes.mul_add(__lane536, __s4, __lane587);
        let __lane590 = __lanes.mul(__lane524, __lanes.splat(__v31));
        let __lane592 = __lanes.mul_add(__lane536, __c4, __lane590);
        let __lane593 = __lanes.neg(__lane592);
        let __lane596 = __lanes.add(__lane527, __lane11);
        let __lane597 = __lanes.mul(__lane11, __lanes.splat(__v38));
        let __lane599 = __lanes.mul_add(__lane593, __qd4, __lane597);
        let __lane600 = __lanes.mul(__lane11, __lanes.splat(__v39));
        let __lane602 = __lanes.mul_add(__lane589, __qd4, __lane600);
        let __lane603 = __lanes.mul_sub(__lane543, __c4, __lane599);
        let __lane604 = __lanes.neg_mul_add(__lane543, __v31, __lane602);
        let __lane605 = __lanes.mul(__lane593, __lanes.splat(__v10));
        let __lane606 = __lanes.neg(__lane605);
        let __lane607 = __lanes.mul(__lane589, __lanes.splat(__v10));
        let __lane608 = __lanes.mul(__lane596, __lanes.splat(__v35));
        let __lane610 = __lanes.mul_add(__lane607, __v36, __lane608);
        let __lane611 = __lanes.mul(__lane593, __lanes.splat(__v37));
        let __lane613 = __lanes.mul_add(__lane606, __v38, __lane611);
        let __lane614 = __lanes.mul(__lane589, __lanes.splat(__v35));
        let __lane616 = __lanes.mul_add(__lane607, __v39, __lane614);
        let __lane617 = __lanes.sub(__lane613, __lane616);
        let __lane618 = __lanes.mul(__lane596, __lanes.splat(__v37));
        let __lane620 = __lanes.mul_add(__lane606, __v36, __lane618);
        let __lane623 = __lanes.neg_mul_add(__lane604, __v10, __lane610);
        let __lane624 = __lanes.mul_sub(__lane603, __v10, __lane620);
        let __lane625 = __lanes.add(__lane583, __lane623);
        let __lane626 = __lanes.add(__lane580, __lane617);
        let __lane627 = __lanes.sub(__lane624, __lane586);
        let __lane628 = __lanes.mul(__lane625, __lanes.splat(__c5));
        let __lane630 = __lanes.mul_add(__lane626, __s5, __lane628);
        let __lane631 = __lanes.mul(__lane625, __lanes.splat(__v42));
        let __lane633 = __lanes.mul_add(__lane626, __c5, __lane631);
        let __lane634 = __lanes.neg(__lane627);
        let __lane635 = __lanes.mul(__lane589, __lanes.splat(__c5));
        let __lane637 = __lanes.mul_add(__lane596, __s5, __lane635);
        let __lane638 = __lanes.mul(__lane589, __lanes.splat(__v42));
        let __lane640 = __lanes.mul_add(__lane596, __c5, __lane638);
        let __lane641 = __lanes.mul(__lane603, __lanes.splat(__c5));
        let __lane643 = __lanes.mul_add(__lane544, __s5, __lane641);
        let __lane644 = __lanes.neg(__lane604);
        let __lane646 = __lanes.neg_mul_add(__lane640, __v43, __lane643);
        let __lane647 = __lanes.mul(__lane630, __lanes.splat(__c6));
        let __lane649 = __lanes.mul_add(__lane634, __s6, __lane647);
        let __lane650 = __lanes.mul(__lane630, __lanes.splat(__v46));
        let __lane652 = __lanes.mul_add(__lane634, __c6, __lane650);
        let __lane653 = __lanes.mul(__lane637, __lanes.splat(__c6));
        let __lane655 = __lanes.mul_add(__lane592, __s6, __lane653);
        let __lane656 = __lanes.mul(__lane637, __lanes.splat(__v46));
        let __lane658 = __lanes.mul_add(__lane592, __c6, __lane656);
        let __lane659 = __lanes.mul(__lane646, __lanes.splat(__c6));
        let __lane661 = __lanes.mul_add(__lane644, __s6, __lane659);
        let __lane662 = __lanes.mul(__lane646, __lanes.splat(__v46));
        let __lane664 = __lanes.mul_add(__lane644, __c6, __lane662);
        let __lane667 = __lanes.mul_add(__lane658, __qd6, __lane661);
        let __lane668 = __lanes.neg_mul_add(__lane655, __qd6, __lane664);
        let __lane669 = __lanes.mul(__lane489, __lanes.splat(__v48));
        let __lane671 = __lanes.neg_mul_add(__lane2, __v49, __lane669);
        let __lane672 = __lanes.mul(__lane2, __lanes.splat(__v50));
        let __lane674 = __lanes.neg_mul_add(__lane488, __v48, __lane672);
        let __lane675 = __lanes.mul(__lane488, __lanes.splat(__v49));
        let __lane677 = __lanes.neg_mul_add(__lane489, __v50, __lane675);
        let __lane678 = __lanes.mul(__lane489, __lanes.splat(__v51));
        let __lane680 = __lanes.mul_add(__lane677, __v12, __lane678);
        let __lane681 = __lanes.mul(__lane2, __lanes.splat(__v52));
        let __lane683 = __lanes.mul_add(__lane674, __qd2, __lane681);
        let __lane684 = __lanes.sub(__lane680, __lane683);
        let __lane685 = __lanes.mul(__lane2, __lanes.splat(__v53));
        let __lane687 = __lanes.mul_add(__lane671, __qd2, __lane685);
        let __lane688 = __lanes.mul(__lane488, __lanes.splat(__v51));
        let __lane690 = __lanes.mul_add(__lane677, __v13, __lane688);
        let __lane691 = __lanes.sub(__lane687, __lane690);
        let __lane692 = __lanes.mul(__lane488, __lanes.splat(__v52));
        let __lane694 = __lanes.mul_add(__lane674, __v13, __lane692);
        let __lane695 = __lanes.mul(__lane489, __lanes.splat(__v53));
        let __lane697 = __lanes.mul_add(__lane671, __v12, __lane695);
        let __lane698 = __lanes.sub(__lane694, __lane697);
        let __lane700 = __lanes.mul(__lane492, __lanes.splat(__v48));
        let __lane701 = __lanes.neg(__lane700);
        let __lane702 = __lanes.mul(__lane492, __lanes.splat(__v49));
        let __lane704 = __lanes.neg_mul_add(__lane496, __v50, __lane702);
        let __lane705 = __lanes.mul_add(__lane496, __v48, __lane684);
        let __lane706 = __lanes.add(__lane691, __lane701);
        let __lane707 = __lanes.add(__lane698, __lane704);
        let __lane708 = __lanes.add(__lane506, __lane705);
        let __lane709 = __lanes.add(__lane514, __lane706);
        let __lane710 = __lanes.add(__lane515, __lane707);
        let __lane711 = __lanes.mul(__lane708, __lanes.splat(__v54));
        let __lane712 = __lanes.mul(__lane709, __lanes.splat(__v54));
        let __lane713 = __lanes.mul(__lane710, __lanes.splat(__v54));
        let __lane714 = __lanes.mul(__lane713, __lanes.splat(__v49));
        let __lane716 = __lanes.neg_mul_add(__lane712, __v48, __lane714);
        let __lane717 = __lanes.mul(__lane711, __lanes.splat(__v48));
        let __lane719 = __lanes.neg_mul_add(__lane713, __v50, __lane717);
        let __lane720 = __lanes.mul(__lane712, __lanes.splat(__v50));
        let __lane722 = __lanes.neg_mul_add(__lane711, __v49, __lane720);
        let __lane723 = __lanes.mul(__lane536, __lanes.splat(__v57));
        let __lane725 = __lanes.neg_mul_add(__lane527, __v55, __lane723);
        let __lane726 = __lanes.mul(__lane527, __lanes.splat(__v56));
        let __lane728 = __lanes.neg_mul_add(__lane524, __v57, __lane726);
        let __lane729 = __lanes.mul(__lane524, __lanes.splat(__v55));
        let __lane731 = __lanes.neg_mul_add(__lane536, __v56, __lane729);
        let __lane732 = __lanes.mul(__lane536, __lanes.splat(__v60));
        let __lane734 = __lanes.mul_add(__lane731, __v23, __lane732);
        let __lane735 = __lanes.mul(__lane527, __lanes.splat(__v58));
        let __lane737 = __lanes.mul_add(__lane728, __v25, __lane735);
        let __lane738 = __lanes.sub(__lane734, __lane737);
        let __lane739 = __lanes.mul(__lane527, __lanes.splat(__v59));
        let __lane741 = __lanes.mul_add(__lane725, __v25, __lane739);
        let __lane742 = __lanes.mul(__lane524, __lanes.splat(__v60));
        let __lane744 = __lanes.mul_add(__lane731, __v28, __lane742);
        let __lane745 = __lanes.sub(__lane741, __lane744);
        let __lane746 = __lanes.mul(__lane524, __lanes.splat(__v58));
        let __lane748 = __lanes.mul_add(__lane728, __v28, __lane746);
        let __lane749 = __lanes.mul(__lane536, __lanes.splat(__v59));
        let __lane751 = __lanes.mul_add(__lane725, __v23, __lane749);
        let __lane752 = __lanes.sub(__lane748, __lane751);
        let __lane753 = __lanes.mul(__lane544, __lanes.splat(__v55));
        let __lane754 = __lanes.neg(__lane753);
        let __lane755 = __lanes.mul(__lane544, __lanes.splat(__v56));
        let __lane757 = __lanes.neg_mul_add(__lane543, __v57, __lane755);
        let __lane759 = __lanes.add(__lane738, __lane754);
        let __lane760 = __lanes.add(__lane745, __lane757);
        let __lane761 = __lanes.mul_add(__lane543, __v55, __lane752);
        let __lane762 = __lanes.add(__lane578, __lane759);
        let __lane763 = __lanes.add(__lane579, __lane760);
        let __lane764 = __lanes.add(__lane580, __lane761);
        let __lane765 = __lanes.mul(__lane762, __lanes.splat(__v61));
        let __lane766 = __lanes.mul(__lane763, __lanes.splat(__v61));
        let __lane767 = __lanes.mul(__lane764, __lanes.splat(__v61));
        let __lane768 = __lanes.mul(__lane767, __lanes.splat(__v55));
        let __lane770 = __lanes.neg_mul_add(__lane766, __v57, __lane768);
        let __lane771 = __lanes.mul(__lane765, __lanes.splat(__v57));
        let __lane773 = __lanes.neg_mul_add(__lane767, __v56, __lane771);
        let __lane774 = __lanes.mul(__lane766, __lanes.splat(__v56));
        let __lane776 = __lanes.neg_mul_add(__lane765, __v55, __lane774);
        let __lane777 = __lanes.mul(__lane593, __lanes.splat(__v62));
        let __lane778 = __lanes.neg(__lane777);
        let __lane779 = __lanes.mul(__lane589, __lanes.splat(__v62));
        let __lane780 = __lanes.mul(__lane596, __lanes.splat(__v63));
        let __lane782 = __lanes.mul_add(__lane779, __v36, __lane780);
        let __lane783 = __lanes.mul(__lane593, __lanes.splat(__v64));
        let __lane785 = __lanes.mul_add(__lane778, __v38, __lane783);
        let __lane786 = __lanes.mul(__lane589, __lanes.splat(__v63));
        let __lane788 = __lanes.mul_add(__lane779, __v39, __lane786);
        let __lane789 = __lanes.sub(__lane785, __lane788);
        let __lane790 = __lanes.mul(__lane596, __lanes.splat(__v64));
        let __lane792 = __lanes.mul_add(__lane778, __v36, __lane790);
        let __lane795 = __lanes.neg_mul_add(__lane604, __v62, __lane782);
        let __lane796 = __lanes.mul_sub(__lane603, __v62, __lane792);
        let __lane797 = __lanes.add(__lane625, __lane795);
        let __lane798 = __lanes.add(__lane626, __lane789);
        let __lane799 = __lanes.add(__lane627, __lane796);
        let __lane800 = __lanes.mul(__lane797, __lanes.splat(__v65));
        let __lane802 = __lanes.mul(__lane799, __lanes.splat(__v65));
        let __lane803 = __lanes.mul(__lane802, __lanes.splat(__v62));
        let __lane804 = __lanes.mul(__lane800, __lanes.splat(__v62));
        let __lane805 = __lanes.neg(__lane804);
        let __lane808 = __lanes.mul(__lane633, __lanes.splat(__v66));
        let __lane809 = __lanes.mul(__lane658, __lanes.splat(__v67));
        let __lane810 = __lanes.mul(__lane655, __lanes.splat(__v67));
        let __lane811 = __lanes.neg(__lane810);
        let __lane812 = __lanes.mul(__lane640, __lanes.splat(__v68));
        let __lane814 = __lanes.mul_add(__lane811, __v69, __lane812);
        let __lane815 = __lanes.mul(__lane640, __lanes.splat(__v70));
        let __lane817 = __lanes.mul_add(__lane809, __v69, __lane815);
        let __lane818 = __lanes.mul(__lane655, __lanes.splat(__v68));
        let __lane820 = __lanes.mul_add(__lane811, __v71, __lane818);
        let __lane821 = __lanes.mul(__lane658, __lanes.splat(__v70));
        let __lane823 = __lanes.mul_add(__lane809, __v72, __lane821);
        let __lane824 = __lanes.sub(__lane820, __lane823);
        let __lane827 = __lanes.mul_sub(__lane668, __v67, __lane814);
        let __lane828 = __lanes.neg_mul_add(__lane667, __v67, __lane817);
        let __lane829 = __lanes.add(__lane649, __lane827);
        let __lane830 = __lanes.add(__lane652, __lane828);
        let __lane831 = __lanes.add(__lane633, __lane824);
        let __lane832 = __lanes.mul(__lane829, __lanes.splat(__v73));
        let __lane833 = __lanes.mul(__lane830, __lanes.splat(__v73));
        let __lane835 = __lanes.mul(__lane833, __lanes.splat(__v67));
        let __lane836 = __lanes.neg(__lane835);
        let __lane837 = __lanes.mul(__lane832, __lanes.splat(__v67));
        let __lane838 = __lanes.mul(__lane832, __lanes.splat(__c6));
        let __lane840 = __lanes.mul_add(__lane833, __v46, __lane838);
        let __lane841 = __lanes.mul(__lane832, __lanes.splat(__s6));
        let __lane843 = __lanes.mul_add(__lane833, __c6, __lane841);
        let __lane844 = __lanes.mul(__lane836, __lanes.splat(__c6));
        let __lane846 = __lanes.mul_add(__lane837, __v46, __lane844);
        let __lane847 = __lanes.mul(__lane836, __lanes.splat(__s6));
        let __lane849 = __lanes.mul_add(__lane837, __c6, __lane847);
        let __lane850 = __lanes.mul_add(__lane630, __v66, __lane840);
        let __lane851 = __lanes.mul_add(__lane634, __v66, __lane843);
        let __lane852 = __lanes.mul_add(__lane831, __v73, __lane808);
        let __lane853 = __lanes.neg(__lane849);
        let __lane854 = __lanes.mul(__lane850, __lanes.splat(__c5));
        let __lane856 = __lanes.mul_add(__lane852, __v42, __lane854);
        let __lane857 = __lanes.mul(__lane850, __lanes.splat(__s5));
        let __lane859 = __lanes.mul_add(__lane852, __c5, __lane857);
        let __lane861 = __lanes.mul(__lane846, __lanes.splat(__s5));
        let __lane862 = __lanes.add(__lane800, __lane856);
        let __lane863 = __lanes.mul_add(__lane798, __v65, __lane859);
        let __lane864 = __lanes.sub(__lane802, __lane851);
        let __lane865 = __lanes.mul_add(__lane846, __c5, __lane803);
        let __lane866 = __lanes.sub(__lane805, __lane849);
        let __lane869 = __lanes.mul_add(__lane864, __v10, __lane865);
        let __lane870 = __lanes.neg_mul_add(__lane862, __v10, __lane866);
        let __lane871 = __lanes.neg(__lane864);
        let __lane872 = __lanes.mul(__lane862, __lanes.splat(__c4));
        let __lane874 = __lanes.mul_add(__lane871, __v31, __lane872);
        let __lane875 = __lanes.mul(__lane862, __lanes.splat(__s4));
        let __lane877 = __lanes.mul_add(__lane871, __c4, __lane875);
        let __lane878 = __lanes.neg(__lane870);
        let __lane879 = __lanes.mul(__lane869, __lanes.splat(__c4));
        let __lane881 = __lanes.mul_add(__lane878, __v31, __lane879);
        let __lane882 = __lanes.mul(__lane869, __lanes.splat(__s4));
        let __lane884 = __lanes.mul_add(__lane878, __c4, __lane882);
        let __lane885 = __lanes.add(__lane765, __lane874);
        let __lane886 = __lanes.add(__lane766, __lane877);
        let __lane887 = __lanes.add(__lane767, __lane863);
        let __lane888 = __lanes.add(__lane770, __lane881);
        let __lane889 = __lanes.add(__lane773, __lane884);
        let __lane890 = __lanes.add(__lane776, __lane861);
        let __lane893 = __lanes.mul(__lane886, __lanes.splat(__v22));
        let __lane895 = __lanes.neg_mul_add(__lane885, __v21, __lane893);
        let __lane896 = __lanes.mul_add(__lane887, __v21, __lane888);
        let __lane897 = __lanes.neg_mul_add(__lane887, __v22, __lane889);
        let __lane898 = __lanes.add(__lane890, __lane895);
        let __lane899 = __lanes.neg(__lane897);
        let __lane900 = __lanes.mul(__lane885, __lanes.splat(__s3));
        let __lane902 = __lanes.mul_add(__lane887, __c3, __lane900);
        let __lane903 = __lanes.mul(__lane896, __lanes.splat(__c3));
        let __lane905 = __lanes.mul_add(__lane898, __v17, __lane903);
        let __lane906 = __lanes.mul(__lane896, __lanes.splat(__s3));
        let __lane908 = __lanes.mul_add(__lane898, __c3, __lane906);
        let __lane909 = __lanes.add(__lane712, __lane902);
        let __lane910 = __lanes.sub(__lane713, __lane886);
        let __lane911 = __lanes.add(__lane716, __lane905);
        let __lane912 = __lanes.add(__lane719, __lane908);
        let __lane913 = __lanes.sub(__lane722, __lane897);
        let __lane916 = __lanes.neg_mul_add(__lane910, __v10, __lane912);
        let __lane917 = __lanes.mul_add(__lane909, __v10, __lane913);
        let __lane918 = __lanes.mul(__lane911, __lanes.splat(__s2));
        let __lane920 = __lanes.mul_add(__lane916, __c2, __lane918);
        let __lane921 = __lanes.constant([-1.0, 0.0, 0.0, 0.0]);
        let __lane922 = __lanes.mul(__lane921, __lanes.splat(__s5));
        let __lane923 = __lanes.mul(__lane487, __lanes.splat(__c5));
        let __lane924 = __lanes.neg(__lane923);
        let __lane925 = __lanes.mul(__lane0, __lanes.splat(__s6));
        let __lane926 = __lanes.mul(__lane2, __lanes.splat(__c6));
        let __lane927 = __lanes.neg(__lane926);
        let __lane928 = __lanes.mul(__lane922, __lanes.splat(__v84));
        let __lane930 = __lanes.mul_add(__lane923, __v85, __lane928);
        let __lane931 = __lanes.mul(__lane924, __lanes.splat(__v84));
        let __lane933 = __lanes.mul_add(__lane922, __v85, __lane931);
        let __lane934 = __lanes.mul(__lane922, __lanes.splat(__v39));
        let __lane936 = __lanes.mul_add(__lane923, __v36, __lane934);
        let __lane937 = __lanes.mul(__lane924, __lanes.splat(__v39));
        let __lane939 = __lanes.mul_add(__lane922, __v36, __lane937);
        let __lane940 = __lanes.mul(__lane922, __lanes.splat(__v86));
        let __lane942 = __lanes.mul_add(__lane923, __v87, __lane940);
        let __lane943 = __lanes.mul(__lane939, __lanes.splat(__v43));
        let __lane945 = __lanes.mul_add(__lane535, __v88, __lane943);
        let __lane946 = __lanes.sub(__lane942, __lane945);
        let __lane947 = __lanes.mul(__lane925, __lanes.splat(__v89));
        let __lane949 = __lanes.mul_add(__lane930, __c6, __lane947);
        let __lane951 = __lanes.mul_add(__lane926, __v90, __lane949);
        let __lane952 = __lanes.mul(__lane927, __lanes.splat(__v89));
        let __lane954 = __lanes.mul_add(__lane930, __v46, __lane952);
        let __lane956 = __lanes.mul_add(__lane925, __v90, __lane954);
        let __lane957 = __lanes.mul(__lane925, __lanes.splat(__v91));
        let __lane959 = __lanes.mul_add(__lane936, __c6, __lane957);
        let __lane960 = __lanes.mul(__lane926, __lanes.splat(__v92));
        let __lane962 = __lanes.mul_add(__lane535, __s6, __lane960);
        let __lane963 = __lanes.add(__lane959, __lane962);
        let __lane964 = __lanes.mul(__lane927, __lanes.splat(__v91));
        let __lane966 = __lanes.mul_add(__lane936, __v46, __lane964);
        let __lane967 = __lanes.mul(__lane925, __lanes.splat(__v92));
        let __lane969 = __lanes.mul_add(__lane535, __c6, __lane967);
        let __lane970 = __lanes.add(__lane966, __lane969);
        let __lane971 = __lanes.mul(__lane925, __lanes.splat(__v93));
        let __lane973 = __lanes.mul_add(__lane946, __c6, __lane971);
        let __lane975 = __lanes.mul_add(__lane926, __v94, __lane973);
        let __lane976 = __lanes.mul(__lane927, __lanes.splat(__v93));
        let __lane978 = __lanes.mul_add(__lane946, __v46, __lane976);
        let __lane980 = __lanes.mul_add(__lane925, __v94, __lane978);
        let __lane981 = __lanes.add(__lane939, __lane11);
        let __lane982 = __lanes.mul(__lane11, __lanes.splat(__v72));
        let __lane984 = __lanes.mul_add(__lane970, __qd6, __lane982);
        let __lane985 = __lanes.mul(__lane11, __lanes.splat(__v71));
        let __lane987 = __lanes.mul_add(__lane963, __qd6, __lane985);
        let __lane988 = __lanes.add(__lane975, __lane984);
        let __lane989 = __lanes.sub(__lane980, __lane987);
        let __lane991 = __lanes.mul(__lane933, __lanes.splat(__v66));
        let __lane992 = __lanes.mul(__lane970, __lanes.splat(__v67));
        let __lane993 = __lanes.mul(__lane963, __lanes.splat(__v67));
        let __lane994 = __lanes.neg(__lane993);
        let __lane995 = __lanes.mul(__lane981, __lanes.splat(__v68));
        let __lane997 = __lanes.mul_add(__lane994, __v69, __lane995);
        let __lane998 = __lanes.mul(__lane981, __lanes.splat(__v70));
        let __lane1000 = __lanes.mul_add(__lane992, __v69, __lane998);
        let __lane1001 = __lanes.mul(__lane963, __lanes.splat(__v68));
        let __lane1003 = __lanes.mul_add(__lane994, __v71, __lane1001);
        let __lane1004 = __lanes.mul(__lane970, __lanes.splat(__v70));
        let __lane1006 = __lanes.mul_add(__lane992, __v72, __lane1004);
        let __lane1007 = __lanes.sub(__lane1003, __lane1006);
        let __lane1010 = __lanes.mul_sub(__lane989, __v67, __lane997);
        let __lane1011 = __lanes.neg_mul_add(__lane988, __v67, __lane1000);
        let __lane1012 = __lanes.add(__lane951, __lane1010);
        let __lane1013 = __lanes.add(__lane956, __lane1011);
        let __lane1014 = __lanes.add(__lane933, __lane1007);
        let __lane1015 = __lanes.mul(__lane1012, __lanes.splat(__v73));
        let __lane1016 = __lanes.mul(__lane1013, __lanes.splat(__v73));
        let __lane1018 = __lanes.mul(__lane1016, __lanes.splat(__v67));
        let __lane1019 = __lanes.neg(__lane1018);
        let __lane1020 = __lanes.mul(__lane1015, __lanes.splat(__v67));
        let __lane1021 = __lanes.mul(__lane925, __lanes.splat(__v95));
        let __lane1023 = __lanes.mul_add(__lane1015, __c6, __lane1021);
        let __lane1024 = __lanes.mul(__lane927, __lanes.splat(__v96));
        let __lane1026 = __lanes.mul_add(__lane1016, __v46, __lane1024);
        let __lane1027 = __lanes.add(__lane1023, __lane1026);
        let __lane1028 = __lanes.mul(__lane926, __lanes.splat(__v95));
        let __lane1030 = __lanes.mul_add(__lane1015, __s6, __lane1028);
        let __lane1031 = __lanes.mul(__lane925, __lanes.splat(__v96));
        let __lane1033 = __lanes.mul_add(__lane1016, __c6, __lane1031);
        let __lane1034 = __lanes.add(__lane1030, __lane1033);
        let __lane1035 = __lanes.mul(__lane925, __lanes.splat(__v97));
        let __lane1037 = __lanes.mul_add(__lane1019, __c6, __lane1035);
        let __lane1038 = __lanes.mul(__lane927, __lanes.splat(__v98));
        let __lane1040 = __lanes.mul_add(__lane1020, __v46, __lane1038);
        let __lane1041 = __lanes.add(__lane1037, __lane1040);
        let __lane1042 = __lanes.mul(__lane926, __lanes.splat(__v97));
        let __lane1044 = __lanes.mul_add(__lane1019, __s6, __lane1042);
        let __lane1045 = __lanes.mul(__lane925, __lanes.splat(__v98));
        let __lane1047 = __lanes.mul_add(__lane1020, __c6, __lane1045);
        let __lane1048 = __lanes.add(__lane1044, __lane1047);
        let __lane1049 = __lanes.mul_add(__lane930, __v66, __lane1027);
        let __lane1050 = __lanes.mul_add(__lane1014, __v73, __lane991);
        let __lane1051 = __lanes.neg(__lane1048);
        let __lane1052 = __lanes.mul(__lane922, __lanes.splat(__v99));
        let __lane1054 = __lanes.mul_add(__lane1049, __c5, __lane1052);
        let __lane1055 = __lanes.mul(__lane924, __lanes.splat(__v100));
        let __lane1057 = __lanes.mul_add(__lane1050, __v42, __lane1055);
        let __lane1058 = __lanes.add(__lane1054, __lane1057);
        let __lane1059 = __lanes.mul(__lane923, __lanes.splat(__v99));
        let __lane1061 = __lanes.mul_add(__lane1049, __s5, __lane1059);
        let __lane1062 = __lanes.mul(__lane922, __lanes.splat(__v100));
        let __lane1064 = __lanes.mul_add(__lane1050, __c5, __lane1062);
        let __lane1065 = __lanes.add(__lane1061, __lane1064);
        let __lane1066 = __lanes.mul(__lane922, __lanes.splat(__v101));
        let __lane1068 = __lanes.mul_add(__lane1041, __c5, __lane1066);
        let __lane1069 = __lanes.mul(__lane923, __lanes.splat(__v101));
        let __lane1071 = __lanes.mul_add(__lane1041, __s5, __lane1069);
        let __lane1072 = __lanes.neg(__lane1034);
        let __lane1075 = __lanes.mul_add(__lane1072, __v10, __lane1068);
        let __lane1076 = __lanes.neg_mul_add(__lane1058, __v10, __lane1051);
        let __lane1077 = __lanes.neg(__lane1072);
        let __lane1078 = __lanes.mul(__lane1058, __lanes.splat(__c4));
        let __lane1080 = __lanes.mul_add(__lane1077, __v31, __lane1078);
        let __lane1081 = __lanes.mul(__lane1058, __lanes.splat(__s4));
        let __lane1083 = __lanes.mul_add(__lane1077, __c4, __lane1081);
        let __lane1084 = __lanes.neg(__lane1076);
        let __lane1085 = __lanes.mul(__lane1075, __lanes.splat(__c4));
        let __lane1087 = __lanes.mul_add(__lane1084, __v31, __lane1085);
        let __lane1088 = __lanes.mul(__lane1075, __lanes.splat(__s4));
        let __lane1090 = __lanes.mul_add(__lane1084, __c4, __lane1088);
        let __lane1093 = __lanes.mul(__lane1083, __lanes.splat(__v22));
        let __lane1095 = __lanes.neg_mul_add(__lane1080, __v21, __lane1093);
        let __lane1096 = __lanes.mul_add(__lane1065, __v21, __lane1087);
        let __lane1097 = __lanes.neg_mul_add(__lane1065, __v22, __lane1090);
        let __lane1098 = __lanes.add(__lane1071, __lane1095);
        let __lane1099 = __lanes.neg(__lane1097);
        let __lane1100 = __lanes.mul(__lane1080, __lanes.splat(__s3));
        let __lane1102 = __lanes.mul_add(__lane1065, __c3, __lane1100);
        let __lane1103 = __lanes.mul(__lane1096, __lanes.splat(__c3));
        let __lane1105 = __lanes.mul_add(__lane1098, __v17, __lane1103);
        let __lane1106 = __lanes.mul(__lane1096, __lanes.splat(__s3));
        let __lane1108 = __lanes.mul_add(__lane1098, __c3, __lane1106);
        let __lane1109 = __lanes.neg(__lane1083);
        let __lane1112 = __lanes.neg_mul_add(__lane1109, __v10, __lane1108);
        let __lane1113 = __lanes.mul_add(__lane1102, __v10, __lane1099);
        let __lane1114 = __lanes.mul(__lane1105, __lanes.splat(__s2));
        let __lane1116 = __lanes.mul_add(__lane1112, __c2, __lane1114);
        let __lane486_0 = __lanes.lanes(__lane486)[0];
        let __lane486_1 = __lanes.lanes(__lane486)[1];
        let __lane486_2 = __lanes.lanes(__lane486)[2];
        let __lane486_3 = __lanes.lanes(__lane486)[3];
        let __lane1116_0 = __lanes.lanes(__lane1116)[0];
        let __lane1116_1 = __lanes.lanes(__lane1116)[1];
        let __lane479_0 = __lanes.lanes(__lane479)[0];
        let __lane479_1 = __lanes.lanes(__lane479)[1];
        let __lane479_2 = __lanes.lanes(__lane479)[2];
        let __lane479_3 = __lanes.lanes(__lane479)[3];
        let __lane1113_0 = __lanes.lanes(__lane1113)[0];
        let __lane1113_1 = __lanes.lanes(__lane1113)[1];
        let __lane449_0 = __lanes.lanes(__lane449)[0];
        let __lane449_1 = __lanes.lanes(__lane449)[1];
        let __lane449_2 = __lanes.lanes(__lane449)[2];
        let __lane449_3 = __lanes.lanes(__lane449)[3];
        let __lane1099_0 = __lanes.lanes(__lane1099)[0];
        let __lane1099_1 = __lanes.lanes(__lane1099)[1];
        let __lane395_0 = __lanes.lanes(__lane395)[0];
        let __lane395_1 = __lanes.lanes(__lane395)[1];
        let __lane395_2 = __lanes.lanes(__lane395)[2];
        let __lane395_3 = __lanes.lanes(__lane395)[3];
        let __lane1071_0 = __lanes.lanes(__lane1071)[0];
        let __lane1071_1 = __lanes.lanes(__lane1071)[1];
        let __lane387_0 = __lanes.lanes(__lane387)[0];
        let __lane387_1 = __lanes.lanes(__lane387)[1];
        let __lane387_2 = __lanes.lanes(__lane387)[2];
        let __lane387_3 = __lanes.lanes(__lane387)[3];
        let __lane1051_0 = __lanes.lanes(__lane1051)[0];
        let __lane1051_1 = __lanes.lanes(__lane1051)[1];
        let __lane_zero = 0.0_f64;
        let __lane920_0 = __lanes.lanes(__lane920)[0];
        let __lane920_1 = __lanes.lanes(__lane920)[1];
        let __lane920_2 = __lanes.lanes(__lane920)[2];
        let __lane920_3 = __lanes.lanes(__lane920)[3];
        let __lane1116_2 = __lanes.lanes(__lane1116)[2];
        let __lane1116_3 = __lanes.lanes(__lane1116)[3];
        let __lane917_0 = __lanes.lanes(__lane917)[0];
        let __lane917_1 = __lanes.lanes(__lane917)[1];
        let __lane917_2 = __lanes.lanes(__lane917)[2];
        let __lane917_3 = __lanes.lanes(__lane917)[3];
        let __lane1113_2 = __lanes.lanes(__lane1113)[2];
        let __lane1113_3 = __lanes.lanes(__lane1113)[3];
        let __lane899_0 = __lanes.lanes(__lane899)[0];
        let __lane899_1 = __lanes.lanes(__lane899)[1];
        let __lane899_2 = __lanes.lanes(__lane899)[2];
        let __lane899_3 = __lanes.lanes(__lane899)[3];
        let __lane1099_2 = __lanes.lanes(__lane1099)[2];
        let __lane1099_3 = __lanes.lanes(__lane1099)[3];
        let __lane861_0 = __lanes.lanes(__lane861)[0];
        let __lane861_1 = __lanes.lanes(__lane861)[1];
        let __lane861_2 = __lanes.lanes(__lane861)[2];
        let __lane861_3 = __lanes.lanes(__lane861)[3];
        let __lane1071_2 = __lanes.lanes(__lane1071)[2];
        let __lane1071_3 = __lanes.lanes(__lane1071)[3];
        let __lane853_0 = __lanes.lanes(__lane853)[0];
        let __lane853_1 = __lanes.lanes(__lane853)[1];
        let __lane853_2 = __lanes.lanes(__lane853)[2];
        let __lane853_3 = __lanes.lanes(__lane853)[3];
        let __lane1051_2 = __lanes.lanes(__lane1051)[2];
        let __lane1051_3 = __lanes.lanes(__lane1051)[3];
        (
            ::planar_arm::__private::columns([
                [
                    __lane486_0,
                    __lane479_0,
                    __lane449_0,
                    __lane395_0,
                    __lane387_0,
                    __lane_zero,
                ],
                [
                    __lane486_1,
                    __lane479_1,
                    __lane449_1,
                    __lane395_1,
                    __lane387_1,
                    __lane_zero,
                ],
                [
                    __lane486_2,
                    __lane479_2,
                    __lane449_2,
                    __lane395_2,
                    __lane387_2,
                    __lane_zero,
                ],
                [
                    __lane486_3,
                    __lane479_3,
                    __lane449_3,
                    __lane395_3,
                    __lane387_3,
                    __lane_zero,
                ],
                [
                    __lane1116_0,
                    __lane1113_0,
                    __lane1099_0,
                    __lane1071_0,
                    __lane1051_0,
                    __lane_zero,
                ],
                [
                    __lane1116_1,
                    __lane1113_1,
                    __lane1099_1,
                    __lane1071_1,
                    __lane1051_1,
                    __lane_zero,
                ],
            ]),
            ::planar_arm::__private::columns([
                [
                    __lane920_0,
                    __lane917_0,
                    __lane899_0,
                    __lane861_0,
                    __lane853_0,
                    __lane_zero,
                ],
                [
                    __lane920_1,
                    __lane917_1,
                    __lane899_1,
                    __lane861_1,
                    __lane853_1,
                    __lane_zero,
                ],
                [
                    __lane920_2,
                    __lane917_2,
                    __lane899_2,
                    __lane861_2,
                    __lane853_2,
                    __lane_zero,
                ],
                [
                    __lane920_3,
                    __lane917_3,
                    __lane899_3,
                    __lane861_3,
                    __lane853_3,
                    __lane_zero,
                ],
                [
                    __lane1116_2,
                    __lane1113_2,
                    __lane1099_2,
                    __lane1071_2,
                    __lane1051_2,
                    __lane_zero,
                ],
                [
                    __lane1116_3,
                    __lane1113_3,
                    __lane1099_3,
                    __lane1071_3,
                    __lane1051_3,
                    __lane_zero,
                ],
            ]),
        )
    }
    #[doc(hidden)]
    type __Frozen = ::planar_arm::__private::Block<0>;
    /// The accelerations qdd that solve M qdd = tau - c - g - f: M and h = c + g + f from
    /// `mass_matrix_and_bias` (one program), then an L D L^T factorisation of M (no
    /// square roots, no allocation), each pivot floored at 2^-52 M_ii. An arm with a
    /// joint that moves no mass, inertia or armature has a singular M and accelerations
    /// that are not finite; `try_forward_dynamics` says so with an `Err`.
    #[inline]
    fn forward_dynamics<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
        __tau: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 6> {
        let (__m, __h) = self.mass_matrix_and_bias(__q, __qd);
        ::planar_arm::__private::forward_solve(
            &__m,
            __tau,
            &__h,
            [::planar_arm::__private::Floor::Relative; 6],
        )
    }
    /// `forward_dynamics` from the frozen view's M and h.
    #[doc(hidden)]
    #[inline]
    fn __forward_dynamics_frozen<__T: ::planar_arm::Real>(
        &self,
        __block: &Self::__Frozen,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
        __tau: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SVector<__T, 6> {
        let (__m, __h) = self.__mass_matrix_and_bias_frozen(__block, __q, __qd);
        ::planar_arm::__private::forward_solve(
            &__m,
            __tau,
            &__h,
            [::planar_arm::__private::Floor::Relative; 6],
        )
    }
    /// The forward dynamics' derivatives in the dispatch's AVX2 and AVX-512 copies: the
    /// default's computation, with M and h compiled into each copy.
    #[doc(hidden)]
    #[inline(always)]
    fn __forward_dynamics_derivatives_packed<__L: ::planar_arm::__private::Lanes>(
        &self,
        __lanes: __L,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
    ) {
        ::planar_arm::__private::forward_derivatives_in(
            self,
            __lanes,
            self.__mass_matrix_and_bias_body(__q, __qd),
            __q,
            __qd,
            __tau,
        )
    }
    /// The kinetic energy qd^T M qd / 2, J, armature included.
    #[inline]
    fn kinetic_energy<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> __T {
        ::planar_arm::__private::kinetic_energy(&self.mass_matrix(__q), __qd)
    }
    #[doc(hidden)]
    #[inline(always)]
    fn __forward_dynamics_derivatives_adjoint<__L: ::planar_arm::__private::Lanes>(
        &self,
        __lanes: __L,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __minv: &::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
    ) {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [__qdd1, __qdd2, __qdd3, __qdd4, __qdd5, _] = ::planar_arm::__private::unpack(
            __qdd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __v9 = -__s3;
        let __v18 = -__s4;
        let __v26 = -__s5;
        let __v31 = -__s6;
        let __v66 = __s2 * __qd1;
        let __v64 = __c2 * __qd1;
        let __v94 = __s2 * __qdd1 + __qd2 * __v64;
        let __v93 = __c2 * __qdd1 - __qd2 * __v66;
        let __v97 = (2159.0 / 5000.0) * __qd2;
        let __v98 = -((2159.0 / 5000.0) * __v64);
        let __t1 = __v66 * __v97 - (2159.0 / 5000.0) * __v93;
        let __v96 = (981.0 / 100.0) * __s2 + __v64 * __v98 - __qd2 * __v97;
        let __v95 = (981.0 / 100.0) * __c2 + (2159.0 / 5000.0) * __qdd2 - __v66 * __v98;
        let __v56 = __c3 * __v66 + __s3 * __v64;
        let __v58 = __v9 * __v66 + __c3 * __v64;
        let __v92 = -__qd3;
        let __v54 = -__qd2 - __qd3;
        let __v85 = -__qdd2 - __qdd3;
        let __v86 = __c3 * __v94 + __s3 * __v93 - __v58 * __v92;
        let __t2 = __v9 * __v94 + __c3 * __v93 + __v56 * __v92;
        let __v89 = -((-(3001.0 / 20000.0)) * __v58);
        let __v90 = (203.0 / 10000.0) * __v58;
        let __v91 = (-(3001.0 / 20000.0)) * __v56 - (203.0 / 10000.0) * __v54;
        let __v88 = __c3 * __v96 + __s3 * __v95 + __v54 * __v91 - __v58 * __v90
            - (-(3001.0 / 20000.0)) * __t2;
        let __v87 = __v58 * __v89 - __v56 * __v91 + (203.0 / 10000.0) * __t2 - __t1;
        let __t3 = __v9 * __v96 + __c3 * __v95 + __v56 * __v90 - __v54 * __v89
            + (-(3001.0 / 20000.0)) * __v86 - (203.0 / 10000.0) * __v85;
        let __v47 = __c4 * __v56 + __s4 * __v54;
        let __t4 = __v18 * __v56 + __c4 * __v54;
        let __v48 = -__t4;
        let __v45 = __v58 + __qd4;
        let __v78 = __t2 + __qdd4;
        let __v79 = __c4 * __v86 + __s4 * __v85 - __qd4 * __v48;
        let __t5 = __qd4 * __v47 - (__v18 * __v86 + __c4 * __v85);
        let __v82 = -((2159.0 / 5000.0) * __v48);
        let __v83 = (2159.0 / 5000.0) * __v47;
        let __v81 = __c4 * __v88 + __s4 * __v87 + __v45 * __v83
            - (2159.0 / 5000.0) * __t5;
        let __v80 = __t3 + __v48 * __v82 - __v47 * __v83;
        let __t6 = (2159.0 / 5000.0) * __v79 - __v45 * __v82
            - (__v18 * __v88 + __c4 * __v87);
        let __v75 = __c5 * __v81 + __s5 * __v80;
        let __t7 = __v26 * __v81 + __c5 * __v80;
        let __v74 = -__t6;
        let __v73 = __c5 * __v47 + __s5 * __v45;
        let __v77 = __v26 * __v47 + __c5 * __v45;
        let __v76 = -__qd5;
        let __v72 = __t4 - __qd5;
        let __v70 = -__t5 - __qdd5;
        let __v71 = __c5 * __v79 + __s5 * __v78 - __v77 * __v76;
        let __v39 = __c6 * __v73 + __s6 * __v72;
        let __v37 = __v31 * __v73 + __c6 * __v72;
        let __v40 = __v77 + __qd6;
        let __v63 = (91.0 / 400.0) * __v64 - (3.0 / 500.0) * __qd2;
        let __v65 = (-(1819.0 / 5000.0)) * __qd2 - (91.0 / 400.0) * __v66;
        let __v67 = (3.0 / 500.0) * __v66 - (-(1819.0 / 5000.0)) * __v64;
        let __t8 = (87.0 / 5.0)
            * (__t1 + __v66 * __v65 - __v64 * __v63 + (3.0 / 500.0) * __v94
                - (-(1819.0 / 5000.0)) * __v93);
        let __v53 = (7.0 / 100.0) * __v54 - (-(141.0 / 10000.0)) * __v58;
        let __v55 = (-(203.0 / 10000.0)) * __v58 - (7.0 / 100.0) * __v56;
        let __v57 = (-(141.0 / 10000.0)) * __v56 - (-(203.0 / 10000.0)) * __v54;
        let __t9 = (24.0 / 5.0)
            * (__v88 + __v54 * __v57 - __v58 * __v55 + (7.0 / 100.0) * __v85
                - (-(141.0 / 10000.0)) * __t2);
        let __t10 = (24.0 / 5.0)
            * (__v87 + __v58 * __v53 - __v56 * __v57 + (-(203.0 / 10000.0)) * __t2
                - (7.0 / 100.0) * __v86);
        let __t11 = (24.0 / 5.0)
            * (__t3 + __v56 * __v55 - __v54 * __v53 + (-(141.0 / 10000.0)) * __v86
                - (-(203.0 / 10000.0)) * __v85);
        let __v44 = -((19.0 / 1000.0) * __v48);
        let __v46 = (19.0 / 1000.0) * __v47;
        let __t12 = (41.0 / 50.0) * (__v81 + __v45 * __v46 - (19.0 / 1000.0) * __t5);
        let __t13 = (41.0 / 50.0) * (__t6 + (19.0 / 1000.0) * __v79 - __v45 * __v44);
        let __v36 = (4.0 / 125.0) * __v37;
        let __v38 = -((4.0 / 125.0) * __v39);
        let __v33 = (9.0 / 100.0)
            * (__c6 * __v75 + __s6 * __v74
                + (4.0 / 125.0) * (__v31 * __v71 + __c6 * __v70 - __qd6 * __v39)
                - __v40 * __v38);
        let __v32 = (9.0 / 100.0)
            * (__v31 * __v75 + __c6 * __v74 + __v40 * __v36
                - (4.0 / 125.0) * (__c6 * __v71 + __s6 * __v70 + __qd6 * __v37));
        let __v29 = -((4.0 / 125.0) * __v32);
        let __v27 = (4.0 / 125.0) * __v33;
        let __v21 = __c6 * __v29 + __v31 * __v27;
        let __v25 = (17.0 / 50.0) * __v75 + __c6 * __v33 + __v31 * __v32;
        let __v24 = (17.0 / 50.0) * __t7
            + (9.0 / 100.0) * (__t7 + __v39 * __v38 - __v37 * __v36);
        let __v20 = __t12 + __c5 * __v25 + __v26 * __v24;
        let __t14 = __t13 - ((17.0 / 50.0) * __v74 + __s6 * __v33 + __c6 * __v32);
        let __v16 = (19.0 / 1000.0) * __t13 + __c5 * __v21 + (2159.0 / 5000.0) * __t14;
        let __v19 = -__t14;
        let __v14 = -(-((19.0 / 1000.0) * __t12) - (__s6 * __v29 + __c6 * __v27)
            - (2159.0 / 5000.0) * __v20);
        let __v11 = __t9 + __c4 * __v20 + __v18 * __v19;
        let __t15 = __t10 + __s4 * __v20 + __c4 * __v19;
        let __v10 = __t11 + (41.0 / 50.0) * (__v80 + __v48 * __v44 - __v47 * __v46)
            + __s5 * __v25 + __c5 * __v24;
        let __v7 = (-(141.0 / 10000.0)) * __t11 - (7.0 / 100.0) * __t10 + __c4 * __v16
            + __v18 * __v14 + (-(3001.0 / 20000.0)) * __v10;
        let __v5 = (-(203.0 / 10000.0)) * __t10 - (-(141.0 / 10000.0)) * __t9
            + __s5 * __v21 + (203.0 / 10000.0) * __t15 - (-(3001.0 / 20000.0)) * __v11;
        let __v2 = (3.0 / 500.0) * __t8
            - (91.0 / 400.0) * (87.0 / 5.0)
                * (__v95 + __qd2 * __v63 - __v66 * __v67 + (-(1819.0 / 5000.0)) * __qdd2
                    - (91.0 / 400.0) * __v94) + __c3 * __v7 + __v9 * __v5;
        let __v0 = (91.0 / 400.0) * (87.0 / 5.0)
            * (__v96 + __v64 * __v67 - __qd2 * __v65 + (91.0 / 400.0) * __v93
                - (3.0 / 500.0) * __qdd2) - (-(1819.0 / 5000.0)) * __t8 + __s3 * __v7
            + __c3 * __v5 - (2159.0 / 5000.0) * (__t8 - __t15);
        let __v4 = (2159.0 / 5000.0);
        let __v12 = (-(3001.0 / 20000.0));
        let __v13 = (203.0 / 10000.0);
        let __v34 = (4.0 / 125.0);
        let __v35 = (9.0 / 100.0);
        let __v41 = (17.0 / 50.0);
        let __v42 = (19.0 / 1000.0);
        let __v43 = (41.0 / 50.0);
        let __v49 = (-(141.0 / 10000.0));
        let __v50 = (-(203.0 / 10000.0));
        let __v51 = (7.0 / 100.0);
        let __v52 = (24.0 / 5.0);
        let __v59 = (3.0 / 500.0);
        let __v60 = (-(1819.0 / 5000.0));
        let __v61 = (91.0 / 400.0);
        let __v62 = (87.0 / 5.0);
        let __v101 = (981.0 / 100.0);
        use ::planar_arm::__private::Wide as _;
        let __wide = ::planar_arm::__private::Lanes::wide(__lanes);
        let __lane0 = __wide
            .constant(::planar_arm::__private::negated_rows(__minv, 0, 0));
        let __lane1 = __wide
            .constant(::planar_arm::__private::negated_rows(__minv, 1, 0));
        let __lane2 = __wide
            .constant(::planar_arm::__private::negated_rows(__minv, 2, 0));
        let __lane3 = __wide
            .constant(::planar_arm::__private::negated_rows(__minv, 3, 0));
        let __lane4 = __wide
            .constant(::planar_arm::__private::negated_rows(__minv, 4, 0));
        let __lane5 = __wide.mul(__lane0, __wide.splat(__v0));
        let __lane6 = __wide.mul(__lane0, __wide.splat(__c2));
        let __lane7 = __wide.mul(__lane0, __wide.splat(__v2));
        let __lane8 = __wide.mul(__lane0, __wide.splat(__s2));
        let __lane9 = __wide.neg(__lane6);
        let __lane10 = __wide.mul(__lane1, __wide.splat(__v4));
        let __lane11 = __wide.mul(__lane9, __wide.splat(__v4));
        let __lane12 = __wide.neg(__lane1);
        let __lane13 = __wide.neg(__lane11);
        let __lane14 = __wide.mul(__lane6, __wide.splat(__v5));
        let __lane15 = __wide.mul(__lane6, __wide.splat(__c3));
        let __lane16 = __wide.mul(__lane6, __wide.splat(__v7));
        let __lane17 = __wide.mul(__lane6, __wide.splat(__s3));
        let __lane18 = __wide.mul(__lane8, __wide.splat(__v5));
        let __lane19 = __wide.mul_add(__lane8, __v9, __lane15);
        let __lane20 = __wide.mul_add(__lane8, __v7, __lane14);
        let __lane21 = __wide.mul_add(__lane8, __c3, __lane17);
        let __lane22 = __wide.mul_add(__lane10, __v10, __lane20);
        let __lane23 = __wide.mul(__lane10, __wide.splat(__c3));
        let __lane24 = __wide.mul_add(__lane10, __v11, __lane16);
        let __lane25 = __wide.mul(__lane10, __wide.splat(__s3));
        let __lane26 = __wide.sub(__lane12, __lane2);
        let __lane27 = __wide.neg(__lane26);
        let __lane28 = __wide.neg(__lane19);
        let __lane29 = __wide.mul_add(__lane28, __v12, __lane25);
        let __lane30 = __wide.mul_add(__lane19, __v13, __lane13);
        let __lane31 = __wide.mul_add(__lane27, __v13, __lane23);
        let __lane32 = __wide.mul_add(__lane21, __v12, __lane31);
        let __lane33 = __wide.add(__lane3, __lane19);
        let __lane34 = __wide.mul(__lane26, __wide.splat(__v14));
        let __lane35 = __wide.mul(__lane26, __wide.splat(__c4));
        let __lane36 = __wide.mul(__lane26, __wide.splat(__v16));
        let __lane37 = __wide.mul(__lane26, __wide.splat(__s4));
        let __lane38 = __wide.mul(__lane21, __wide.splat(__v14));
        let __lane39 = __wide.mul_add(__lane21, __v18, __lane35);
        let __lane40 = __wide.mul_add(__lane21, __v16, __lane34);
        let __lane41 = __wide.mul_add(__lane21, __c4, __lane37);
        let __lane42 = __wide.neg(__lane39);
        let __lane43 = __wide.mul_add(__lane30, __v19, __lane40);
        let __lane44 = __wide.mul(__lane30, __wide.splat(__c4));
        let __lane45 = __wide.mul_add(__lane30, __v20, __lane36);
        let __lane46 = __wide.mul(__lane30, __wide.splat(__s4));
        let __lane47 = __wide.mul_add(__lane29, __v19, __lane38);
        let __lane48 = __wide.mul_add(__lane29, __v18, __lane44);
        let __lane49 = __wide.mul_add(__lane29, __v20, __lane43);
        let __lane50 = __wide.mul_add(__lane29, __c4, __lane46);
        let __lane51 = __wide.neg(__lane48);
        let __lane52 = __wide.neg(__lane42);
        let __lane53 = __wide.mul_add(__lane52, __v4, __lane50);
        let __lane54 = __wide.mul_add(__lane41, __v4, __lane51);
        let __lane55 = __wide.neg(__lane54);
        let __lane56 = __wide.mul(__lane33, __wide.splat(__v21));
        let __lane57 = __wide.mul(__lane33, __wide.splat(__s5));
        let __lane58 = __wide.mul(__lane41, __wide.splat(__v21));
        let __lane59 = __wide.mul_add(__lane41, __c5, __lane57);
        let __lane60 = __wide.mul_add(__lane32, __v24, __lane58);
        let __lane61 = __wide.mul(__lane32, __wide.splat(__c5));
        let __lane62 = __wide.mul_add(__lane32, __v25, __lane56);
        let __lane63 = __wide.mul(__lane32, __wide.splat(__s5));
        let __lane64 = __wide.mul(__lane53, __wide.splat(__v24));
        let __lane65 = __wide.mul_add(__lane53, __v26, __lane61);
        let __lane66 = __wide.mul_add(__lane53, __v25, __lane60);
        let __lane67 = __wide.mul_add(__lane53, __c5, __lane63);
        let __lane68 = __wide.sub(__lane52, __lane4);
        let __lane69 = __wide.mul(__lane68, __wide.splat(__v27));
        let __lane70 = __wide.mul(__lane68, __wide.splat(__c6));
        let __lane71 = __wide.mul(__lane68, __wide.splat(__v29));
        let __lane72 = __wide.mul(__lane68, __wide.splat(__s6));
        let __lane73 = __wide.mul(__lane59, __wide.splat(__v27));
        let __lane74 = __wide.mul_add(__lane59, __v31, __lane70);
        let __lane75 = __wide.mul_add(__lane59, __v29, __lane69);
        let __lane76 = __wide.mul_add(__lane59, __c6, __lane72);
        let __lane77 = __wide.mul_add(__lane55, __v32, __lane75);
        let __lane78 = __wide.mul(__lane55, __wide.splat(__c6));
        let __lane79 = __wide.mul_add(__lane55, __v33, __lane71);
        let __lane80 = __wide.mul(__lane55, __wide.splat(__s6));
        let __lane81 = __wide.mul_add(__lane67, __v32, __lane73);
        let __lane82 = __wide.mul_add(__lane67, __v31, __lane78);
        let __lane83 = __wide.mul_add(__lane67, __v33, __lane77);
        let __lane84 = __wide.mul_add(__lane67, __c6, __lane80);
        let __lane85 = __wide.mul_add(__lane74, __v34, __lane84);
        let __lane86 = __wide.neg(__lane76);
        let __lane87 = __wide.mul_add(__lane86, __v34, __lane82);
        let __lane88 = __wide.mul(__lane65, __wide.splat(__v35));
        let __lane89 = __wide.mul(__lane87, __wide.splat(__v35));
        let __lane90 = __wide.mul(__lane85, __wide.splat(__v35));
        let __lane91 = __wide.neg(__lane89);
        let __lane92 = __wide.neg(__lane90);
        let __lane93 = __wide.mul(__lane91, __wide.splat(__v34));
        let __lane94 = __wide.mul(__lane90, __wide.splat(__v34));
        let __lane95 = __wide.neg(__lane88);
        let __lane96 = __wide.mul(__lane95, __wide.splat(__v36));
        let __lane97 = __wide.mul(__lane95, __wide.splat(__v37));
        let __lane98 = __wide.mul(__lane88, __wide.splat(__v38));
        let __lane99 = __wide.mul(__lane88, __wide.splat(__v39));
        let __lane100 = __wide.mul(__lane89, __wide.splat(__v36));
        let __lane101 = __wide.mul_add(__lane89, __v40, __lane97);
        let __lane102 = __wide.mul_add(__lane92, __v38, __lane100);
        let __lane103 = __wide.mul_add(__lane92, __v40, __lane99);
        let __lane104 = __wide.neg(__lane103);
        let __lane105 = __wide.mul_add(__lane104, __v34, __lane98);
        let __lane106 = __wide.mul_add(__lane101, __v34, __lane96);
        let __lane107 = __wide.mul_add(__lane65, __v41, __lane88);
        let __lane108 = __wide.mul(__lane55, __wide.splat(__v41));
        let __lane109 = __wide.mul(__lane67, __wide.splat(__v41));
        let __lane110 = __wide.mul_add(__lane52, __v42, __lane53);
        let __lane111 = __wide.mul_add(__lane41, __v42, __lane54);
        let __lane112 = __wide.mul(__lane111, __wide.splat(__v43));
        let __lane113 = __wide.mul(__lane32, __wide.splat(__v43));
        let __lane114 = __wide.mul(__lane110, __wide.splat(__v43));
        let __lane115 = __wide.neg(__lane112);
        let __lane116 = __wide.neg(__lane114);
        let __lane117 = __wide.mul(__lane112, __wide.splat(__v42));
        let __lane118 = __wide.mul(__lane116, __wide.splat(__v42));
        let __lane119 = __wide.mul(__lane115, __wide.splat(__v44));
        let __lane120 = __wide.mul(__lane115, __wide.splat(__v45));
        let __lane121 = __wide.neg(__lane113);
        let __lane122 = __wide.mul(__lane121, __wide.splat(__v46));
        let __lane123 = __wide.mul(__lane121, __wide.splat(__v47));
        let __lane124 = __wide.mul(__lane113, __wide.splat(__v44));
        let __lane125 = __wide.mul_add(__lane113, __v48, __lane120);
        let __lane126 = __wide.mul_add(__lane114, __v46, __lane119);
        let __lane127 = __wide.mul_add(__lane114, __v45, __lane123);
        let __lane128 = __wide.mul_add(__lane127, __v42, __lane122);
        let __lane129 = __wide.neg(__lane125);
        let __lane130 = __wide.mul_add(__lane129, __v42, __lane124);
        let __lane131 = __wide.mul_add(__lane28, __v49, __lane29);
        let __lane132 = __wide.mul_add(__lane19, __v50, __lane30);
        let __lane133 = __wide.mul_add(__lane27, __v50, __lane32);
        let __lane134 = __wide.mul_add(__lane26, __v51, __lane131);
        let __lane135 = __wide.neg(__lane21);
        let __lane136 = __wide.mul_add(__lane135, __v51, __lane132);
        let __lane137 = __wide.mul_add(__lane21, __v49, __lane133);
        let __lane138 = __wide.mul(__lane137, __wide.splat(__v52));
        let __lane139 = __wide.mul(__lane136, __wide.splat(__v52));
        let __lane140 = __wide.mul(__lane134, __wide.splat(__v52));
        let __lane141 = __wide.mul(__lane138, __wide.splat(__v49));
        let __lane142 = __wide.neg(__lane139);
        let __lane143 = __wide.mul_add(__lane142, __v51, __lane141);
        let __lane144 = __wide.mul(__lane139, __wide.splat(__v50));
        let __lane145 = __wide.neg(__lane140);
        let __lane146 = __wide.mul_add(__lane145, __v49, __lane144);
        let __lane147 = __wide.neg(__lane138);
        let __lane148 = __wide.mul(__lane147, __wide.splat(__v53));
        let __lane149 = __wide.mul(__lane147, __wide.splat(__v54));
        let __lane150 = __wide.mul(__lane138, __wide.splat(__v55));
        let __lane151 = __wide.mul(__lane138, __wide.splat(__v56));
        let __lane152 = __wide.mul_add(__lane142, __v57, __lane150);
        let __lane153 = __wide.mul(__lane142, __wide.splat(__v56));
        let __lane154 = __wide.mul(__lane139, __wide.splat(__v53));
        let __lane155 = __wide.mul_add(__lane139, __v58, __lane149);
        let __lane156 = __wide.mul_add(__lane145, __v55, __lane154);
        let __lane157 = __wide.mul_add(__lane145, __v58, __lane151);
        let __lane158 = __wide.mul_add(__lane140, __v57, __lane148);
        let __lane159 = __wide.mul_add(__lane140, __v54, __lane153);
        let __lane160 = __wide.neg(__lane159);
        let __lane161 = __wide.mul_add(__lane160, __v50, __lane158);
        let __lane162 = __wide.mul_add(__lane159, __v49, __lane152);
        let __lane163 = __wide.neg(__lane157);
        let __lane164 = __wide.mul_add(__lane163, __v51, __lane162);
        let __lane165 = __wide.mul_add(__lane157, __v50, __lane156);
        let __lane166 = __wide.neg(__lane155);
        let __lane167 = __wide.mul_add(__lane166, __v49, __lane165);
        let __lane168 = __wide.mul_add(__lane155, __v51, __lane161);
        let __lane169 = __wide.mul(__lane12, __wide.splat(__v59));
        let __lane170 = __wide.mul_add(__lane1, __v60, __lane10);
        let __lane171 = __wide.mul_add(__lane9, __v60, __lane11);
        let __lane172 = __wide.mul_add(__lane6, __v61, __lane169);
        let __lane173 = __wide.neg(__lane8);
        let __lane174 = __wide.mul_add(__lane173, __v61, __lane170);
        let __lane175 = __wide.mul_add(__lane8, __v59, __lane171);
        let __lane176 = __wide.mul(__lane175, __wide.splat(__v62));
        let __lane177 = __wide.mul(__lane174, __wide.splat(__v62));
        let __lane178 = __wide.mul(__lane172, __wide.splat(__v62));
        let __lane179 = __wide.neg(__lane176);
        let __lane180 = __wide.mul(__lane179, __wide.splat(__v60));
        let __lane181 = __wide.mul(__lane176, __wide.splat(__v59));
        let __lane182 = __wide.neg(__lane177);
        let __lane183 = __wide.mul_add(__lane182, __v61, __lane181);
        let __lane184 = __wide.mul_add(__lane178, __v61, __lane180);
        let __lane185 = __wide.mul(__lane179, __wide.splat(__v63));
        let __lane186 = __wide.mul(__lane179, __wide.splat(__v64));
        let __lane187 = __wide.mul(__lane176, __wide.splat(__v65));
        let __lane188 = __wide.mul(__lane176, __wide.splat(__v66));
        let __lane189 = __wide.mul_add(__lane182, __v67, __lane187);
        let __lane190 = __wide.mul(__lane182, __wide.splat(__v66));
        let __lane191 = __wide.mul(__lane177, __wide.splat(__v63));
        let __lane192 = __wide.mul_add(__lane177, __qd2, __lane186);
        let __lane193 = __wide.neg(__lane178);
        let __lane194 = __wide.mul_add(__lane193, __v65, __lane191);
        let __lane195 = __wide.mul_add(__lane193, __qd2, __lane188);
        let __lane196 = __wide.mul_add(__lane178, __v67, __lane185);
        let __lane197 = __wide.mul_add(__lane178, __v64, __lane190);
        let __lane198 = __wide.neg(__lane197);
        let __lane199 = __wide.mul_add(__lane198, __v60, __lane196);
        let __lane200 = __wide.mul_add(__lane197, __v59, __lane189);
        let __lane201 = __wide.neg(__lane195);
        let __lane202 = __wide.mul_add(__lane201, __v61, __lane200);
        let __lane203 = __wide.mul_add(__lane195, __v60, __lane194);
        let __lane204 = __wide.neg(__lane192);
        let __lane205 = __wide.mul_add(__lane204, __v59, __lane203);
        let __lane206 = __wide.mul_add(__lane192, __v61, __lane199);
        let __lane207 = __wide.neg(__lane94);
        let __lane208 = __wide.mul(__lane207, __wide.splat(__v39));
        let __lane209 = __wide.mul_add(__lane207, __qd6, __lane105);
        let __lane210 = __wide.mul_add(__lane93, __v37, __lane208);
        let __lane211 = __wide.mul_add(__lane93, __qd6, __lane106);
        let __lane212 = __wide.add(__lane210, __lane102);
        let __lane213 = __wide.mul_add(__lane94, __v70, __lane83);
        let __lane214 = __wide.mul(__lane94, __wide.splat(__c6));
        let __lane215 = __wide.mul_add(__lane94, __v71, __lane81);
        let __lane216 = __wide.mul(__lane94, __wide.splat(__v31));
        let __lane217 = __wide.mul_add(__lane93, __v70, __lane79);
        let __lane218 = __wide.mul_add(__lane93, __s6, __lane214);
        let __lane219 = __wide.mul_add(__lane93, __v71, __lane213);
        let __lane220 = __wide.mul_add(__lane93, __c6, __lane216);
        let __lane221 = __wide.mul_add(__lane211, __v72, __lane219);
        let __lane222 = __wide.mul(__lane211, __wide.splat(__c6));
        let __lane223 = __wide.mul_add(__lane211, __v73, __lane215);
        let __lane224 = __wide.mul(__lane211, __wide.splat(__v31));
        let __lane225 = __wide.mul_add(__lane209, __v72, __lane217);
        let __lane226 = __wide.mul_add(__lane209, __s6, __lane222);
        let __lane227 = __wide.mul_add(__lane209, __v73, __lane221);
        let __lane228 = __wide.mul_add(__lane209, __c6, __lane224);
        let __lane229 = __wide.mul_add(__lane89, __v74, __lane227);
        let __lane230 = __wide.mul_add(__lane89, __c6, __lane108);
        let __lane231 = __wide.mul_add(__lane89, __v75, __lane223);
        let __lane232 = __wide.mul_add(__lane89, __v31, __lane109);
        let __lane233 = __wide.mul_add(__lane90, __v74, __lane225);
        let __lane234 = __wide.mul_add(__lane90, __s6, __lane230);
        let __lane235 = __wide.mul_add(__lane90, __v75, __lane229);
        let __lane236 = __wide.mul_add(__lane90, __c6, __lane232);
        let __lane237 = __wide.neg(__lane220);
        let __lane238 = __wide.mul_add(__lane237, __v76, __lane102);
        let __lane239 = __wide.mul(__lane237, __wide.splat(__v77));
        let __lane240 = __wide.neg(__lane226);
        let __lane241 = __wide.sub(__lane240, __lane239);
        let __lane242 = __wide.sub(__lane118, __lane218);
        let __lane243 = __wide.mul_add(__lane220, __v78, __lane62);
        let __lane244 = __wide.mul(__lane220, __wide.splat(__s5));
        let __lane245 = __wide.mul_add(__lane220, __v79, __lane66);
        let __lane246 = __wide.mul_add(__lane220, __c5, __lane117);
        let __lane247 = __wide.mul_add(__lane238, __v45, __lane245);
        let __lane248 = __wide.mul_add(__lane238, __c5, __lane126);
        let __lane249 = __wide.mul_add(__lane238, __v47, __lane64);
        let __lane250 = __wide.mul_add(__lane238, __v26, __lane128);
        let __lane251 = __wide.mul_add(__lane228, __v45, __lane243);
        let __lane252 = __wide.mul_add(__lane228, __s5, __lane248);
        let __lane253 = __wide.mul_add(__lane228, __v47, __lane247);
        let __lane254 = __wide.mul_add(__lane228, __c5, __lane250);
        let __lane255 = __wide.sub(__lane112, __lane234);
        let __lane256 = __wide.mul_add(__lane107, __v80, __lane253);
        let __lane257 = __wide.mul_add(__lane107, __c5, __lane113);
        let __lane258 = __wide.mul_add(__lane107, __v81, __lane249);
        let __lane259 = __wide.mul_add(__lane107, __v26, __lane114);
        let __lane260 = __wide.mul_add(__lane236, __v80, __lane251);
        let __lane261 = __wide.mul_add(__lane236, __s5, __lane257);
        let __lane262 = __wide.mul_add(__lane236, __v81, __lane256);
        let __lane263 = __wide.mul_add(__lane236, __c5, __lane259);
        let __lane264 = __wide.neg(__lane255);
        let __lane265 = __wide.add(__lane138, __lane261);
        let __lane266 = __wide.neg(__lane263);
        let __lane267 = __wide.mul_add(__lane255, __v4, __lane246);
        let __lane268 = __wide.mul_add(__lane266, __v4, __lane242);
        let __lane269 = __wide.mul_add(__lane264, __v82, __lane252);
        let __lane270 = __wide.mul(__lane264, __wide.splat(__v45));
        let __lane271 = __wide.neg(__lane261);
        let __lane272 = __wide.mul_add(__lane271, __v83, __lane254);
        let __lane273 = __wide.mul(__lane271, __wide.splat(__v47));
        let __lane274 = __wide.mul_add(__lane261, __v82, __lane130);
        let __lane275 = __wide.mul_add(__lane261, __v48, __lane270);
        let __lane276 = __wide.mul_add(__lane263, __v83, __lane269);
        let __lane277 = __wide.mul_add(__lane263, __v45, __lane273);
        let __lane278 = __wide.mul_add(__lane277, __v4, __lane272);
        let __lane279 = __wide.neg(__lane275);
        let __lane280 = __wide.mul_add(__lane279, __v4, __lane274);
        let __lane281 = __wide.neg(__lane268);
        let __lane282 = __wide.neg(__lane267);
        let __lane283 = __wide.add(__lane146, __lane244);
        let __lane284 = __wide.mul(__lane268, __wide.splat(__v47));
        let __lane285 = __wide.mul_add(__lane268, __qd4, __lane278);
        let __lane286 = __wide.mul_add(__lane282, __v48, __lane284);
        let __lane287 = __wide.mul_add(__lane282, __qd4, __lane280);
        let __lane288 = __wide.add(__lane167, __lane276);
        let __lane289 = __wide.add(__lane286, __lane276);
        let __lane290 = __wide.mul_add(__lane281, __v85, __lane49);
        let __lane291 = __wide.mul_add(__lane281, __v86, __lane47);
        let __lane292 = __wide.mul_add(__lane281, __v18, __lane143);
        let __lane293 = __wide.mul_add(__lane267, __v85, __lane45);
        let __lane294 = __wide.mul_add(__lane267, __v86, __lane290);
        let __lane295 = __wide.mul_add(__lane267, __c4, __lane292);
        let __lane296 = __wide.sub(__lane226, __lane287);
        let __lane297 = __wide.mul_add(__lane296, __v54, __lane294);
        let __lane298 = __wide.mul_add(__lane296, __c4, __lane168);
        let __lane299 = __wide.mul_add(__lane296, __v56, __lane291);
        let __lane300 = __wide.mul_add(__lane296, __v18, __lane164);
        let __lane301 = __wide.mul_add(__lane285, __v54, __lane293);
        let __lane302 = __wide.mul_add(__lane285, __s4, __lane298);
        let __lane303 = __wide.mul_add(__lane285, __v56, __lane297);
        let __lane304 = __wide.mul_add(__lane285, __c4, __lane300);
        let __lane305 = __wide.mul_add(__lane264, __v87, __lane303);
        let __lane306 = __wide.mul_add(__lane264, __c4, __lane139);
        let __lane307 = __wide.mul_add(__lane264, __v88, __lane299);
        let __lane308 = __wide.mul_add(__lane264, __v18, __lane140);
        let __lane309 = __wide.mul_add(__lane263, __v87, __lane301);
        let __lane310 = __wide.mul_add(__lane263, __s4, __lane306);
        let __lane311 = __wide.mul_add(__lane263, __v88, __lane305);
        let __lane312 = __wide.mul_add(__lane263, __c4, __lane308);
        let __lane313 = __wide.sub(__lane176, __lane310);
        let __lane314 = __wide.neg(__lane312);
        let __lane315 = __wide.mul_add(__lane265, __v12, __lane295);
        let __lane316 = __wide.mul_add(__lane310, __v13, __lane283);
        let __lane317 = __wide.mul_add(__lane314, __v12, __lane316);
        let __lane318 = __wide.neg(__lane265);
        let __lane319 = __wide.mul_add(__lane318, __v89, __lane302);
        let __lane320 = __wide.mul(__lane318, __wide.splat(__v54));
        let __lane321 = __wide.mul_add(__lane265, __v90, __lane304);
        let __lane322 = __wide.mul(__lane265, __wide.splat(__v56));
        let __lane323 = __wide.neg(__lane310);
        let __lane324 = __wide.mul_add(__lane323, __v91, __lane321);
        let __lane325 = __wide.mul(__lane323, __wide.splat(__v56));
        let __lane326 = __wide.mul_add(__lane310, __v89, __lane288);
        let __lane327 = __wide.mul_add(__lane310, __v58, __lane320);
        let __lane328 = __wide.mul_add(__lane314, __v90, __lane326);
        let __lane329 = __wide.mul_add(__lane314, __v58, __lane322);
        let __lane330 = __wide.mul_add(__lane312, __v91, __lane319);
        let __lane331 = __wide.mul_add(__lane312, __v54, __lane325);
        let __lane332 = __wide.neg(__lane331);
        let __lane333 = __wide.mul_add(__lane332, __v13, __lane330);
        let __lane334 = __wide.mul_add(__lane331, __v12, __lane324);
        let __lane335 = __wide.mul_add(__lane329, __v13, __lane328);
        let __lane336 = __wide.neg(__lane327);
        let __lane337 = __wide.mul_add(__lane336, __v12, __lane335);
        let __lane338 = __wide.neg(__lane315);
        let __lane339 = __wide.mul_add(__lane317, __v92, __lane334);
        let __lane340 = __wide.mul(__lane317, __wide.splat(__v56));
        let __lane341 = __wide.mul_add(__lane338, __v92, __lane337);
        let __lane342 = __wide.mul_add(__lane338, __v58, __lane340);
        let __lane343 = __wide.neg(__lane333);
        let __lane344 = __wide.sub(__lane343, __lane342);
        let __lane345 = __wide.mul_add(__lane317, __v93, __lane22);
        let __lane346 = __wide.mul_add(__lane317, __c3, __lane184);
        let __lane347 = __wide.mul_add(__lane317, __v94, __lane18);
        let __lane348 = __wide.mul_add(__lane317, __v9, __lane183);
        let __lane349 = __wide.mul_add(__lane315, __v93, __lane24);
        let __lane350 = __wide.mul_add(__lane315, __s3, __lane346);
        let __lane351 = __wide.mul_add(__lane315, __v94, __lane345);
        let __lane352 = __wide.mul_add(__lane315, __c3, __lane348);
        let __lane353 = __wide.sub(__lane205, __lane333);
        let __lane354 = __wide.mul_add(__lane341, __v64, __lane351);
        let __lane355 = __wide.mul_add(__lane341, __c3, __lane206);
        let __lane356 = __wide.mul_add(__lane341, __v66, __lane347);
        let __lane357 = __wide.mul_add(__lane341, __v9, __lane202);
        let __lane358 = __wide.mul_add(__lane339, __v64, __lane349);
        let __lane359 = __wide.mul_add(__lane339, __s3, __lane355);
        let __lane360 = __wide.mul_add(__lane339, __v66, __lane354);
        let __lane361 = __wide.mul_add(__lane339, __c3, __lane357);
        let __lane362 = __wide.mul_add(__lane265, __v95, __lane360);
        let __lane363 = __wide.mul_add(__lane265, __c3, __lane177);
        let __lane364 = __wide.mul_add(__lane265, __v96, __lane356);
        let __lane365 = __wide.mul_add(__lane265, __v9, __lane178);
        let __lane366 = __wide.mul_add(__lane312, __v95, __lane358);
        let __lane367 = __wide.mul_add(__lane312, __s3, __lane363);
        let __lane368 = __wide.mul_add(__lane312, __v96, __lane362);
        let __lane369 = __wide.mul_add(__lane312, __c3, __lane365);
        let __lane370 = __wide.neg(__lane313);
        let __lane371 = __wide.neg(__lane367);
        let __lane372 = __wide.mul_add(__lane370, __v4, __lane350);
        let __lane373 = __wide.mul_add(__lane313, __v97, __lane361);
        let __lane374 = __wide.mul(__lane313, __wide.splat(__v66));
        let __lane375 = __wide.mul_add(__lane371, __v98, __lane373);
        let __lane376 = __wide.mul(__lane371, __wide.splat(__v66));
        let __lane377 = __wide.neg(__lane369);
        let __lane378 = __wide.mul_add(__lane377, __v97, __lane353);
        let __lane379 = __wide.mul_add(__lane377, __qd2, __lane374);
        let __lane380 = __wide.mul_add(__lane369, __v98, __lane359);
        let __lane381 = __wide.mul_add(__lane369, __v64, __lane376);
        let __lane382 = __wide.neg(__lane381);
        let __lane383 = __wide.mul_add(__lane382, __v4, __lane380);
        let __lane384 = __wide.mul_add(__lane379, __v4, __lane378);
        let __lane385 = __wide.neg(__lane372);
        let __lane386 = __wide.mul_add(__lane385, __v66, __lane384);
        let __lane387 = __wide.mul_add(__lane385, __qd2, __lane375);
        let __lane388 = __wide.mul_add(__lane352, __v64, __lane386);
        let __lane389 = __wide.mul_add(__lane352, __qd2, __lane383);
        let __lane390 = __wide.mul_add(__lane372, __qdd1, __lane5);
        let __lane391 = __wide.mul_add(__lane352, __qdd1, __lane7);
        let __lane392 = __wide.mul_add(__lane389, __qd1, __lane390);
        let __lane393 = __wide.mul(__lane389, __wide.splat(__c2));
        let __lane394 = __wide.mul_add(__lane387, __qd1, __lane391);
        let __lane395 = __wide.mul_add(__lane387, __s2, __lane393);
        let __lane396 = __wide.mul_add(__lane367, __v101, __lane392);
        let __lane397 = __wide.mul_add(__lane369, __v101, __lane394);
        let __lane398 = __wide.sub(__lane233, __lane231);
        let __lane399 = __wide.mul(__lane398, __wide.splat(__c6));
        let __lane400 = __wide.neg_mul_add(__lane235, __s6, __lane399);
        let __lane401 = __wide.sub(__lane260, __lane258);
        let __lane402 = __wide.mul(__lane401, __wide.splat(__c5));
        let __lane403 = __wide.neg_mul_add(__lane262, __s5, __lane402);
        let __lane404 = __wide.sub(__lane309, __lane307);
        let __lane405 = __wide.mul(__lane404, __wide.splat(__c4));
        let __lane406 = __wide.neg_mul_add(__lane311, __s4, __lane405);
        let __lane407 = __wide.sub(__lane366, __lane364);
        let __lane408 = __wide.mul(__lane407, __wide.splat(__c3));
        let __lane409 = __wide.neg_mul_add(__lane368, __s3, __lane408);
        let __lane410 = __wide.mul(__lane397, __wide.splat(__c2));
        let __lane411 = __wide.neg_mul_add(__lane396, __s2, __lane410);
        let __lane_zero = 0.0_f64;
        let __lane411_0 = __wide.lanes(__lane411)[0];
        let __lane409_0 = __wide.lanes(__lane409)[0];
        let __lane406_0 = __wide.lanes(__lane406)[0];
        let __lane403_0 = __wide.lanes(__lane403)[0];
        let __lane400_0 = __wide.lanes(__lane400)[0];
        let __lane411_1 = __wide.lanes(__lane411)[1];
        let __lane409_1 = __wide.lanes(__lane409)[1];
        let __lane406_1 = __wide.lanes(__lane406)[1];
        let __lane403_1 = __wide.lanes(__lane403)[1];
        let __lane400_1 = __wide.lanes(__lane400)[1];
        let __lane411_2 = __wide.lanes(__lane411)[2];
        let __lane409_2 = __wide.lanes(__lane409)[2];
        let __lane406_2 = __wide.lanes(__lane406)[2];
        let __lane403_2 = __wide.lanes(__lane403)[2];
        let __lane400_2 = __wide.lanes(__lane400)[2];
        let __lane411_3 = __wide.lanes(__lane411)[3];
        let __lane409_3 = __wide.lanes(__lane409)[3];
        let __lane406_3 = __wide.lanes(__lane406)[3];
        let __lane403_3 = __wide.lanes(__lane403)[3];
        let __lane400_3 = __wide.lanes(__lane400)[3];
        let __lane411_4 = __wide.lanes(__lane411)[4];
        let __lane409_4 = __wide.lanes(__lane409)[4];
        let __lane406_4 = __wide.lanes(__lane406)[4];
        let __lane403_4 = __wide.lanes(__lane403)[4];
        let __lane400_4 = __wide.lanes(__lane400)[4];
        let __lane411_5 = __wide.lanes(__lane411)[5];
        let __lane409_5 = __wide.lanes(__lane409)[5];
        let __lane406_5 = __wide.lanes(__lane406)[5];
        let __lane403_5 = __wide.lanes(__lane403)[5];
        let __lane400_5 = __wide.lanes(__lane400)[5];
        let __lane395_0 = __wide.lanes(__lane395)[0];
        let __lane388_0 = __wide.lanes(__lane388)[0];
        let __lane344_0 = __wide.lanes(__lane344)[0];
        let __lane289_0 = __wide.lanes(__lane289)[0];
        let __lane241_0 = __wide.lanes(__lane241)[0];
        let __lane212_0 = __wide.lanes(__lane212)[0];
        let __lane395_1 = __wide.lanes(__lane395)[1];
        let __lane388_1 = __wide.lanes(__lane388)[1];
        let __lane344_1 = __wide.lanes(__lane344)[1];
        let __lane289_1 = __wide.lanes(__lane289)[1];
        let __lane241_1 = __wide.lanes(__lane241)[1];
        let __lane212_1 = __wide.lanes(__lane212)[1];
        let __lane395_2 = __wide.lanes(__lane395)[2];
        let __lane388_2 = __wide.lanes(__lane388)[2];
        let __lane344_2 = __wide.lanes(__lane344)[2];
        let __lane289_2 = __wide.lanes(__lane289)[2];
        let __lane241_2 = __wide.lanes(__lane241)[2];
        let __lane212_2 = __wide.lanes(__lane212)[2];
        let __lane395_3 = __wide.lanes(__lane395)[3];
        let __lane388_3 = __wide.lanes(__lane388)[3];
        let __lane344_3 = __wide.lanes(__lane344)[3];
        let __lane289_3 = __wide.lanes(__lane289)[3];
        let __lane241_3 = __wide.lanes(__lane241)[3];
        let __lane212_3 = __wide.lanes(__lane212)[3];
        let __lane395_4 = __wide.lanes(__lane395)[4];
        let __lane388_4 = __wide.lanes(__lane388)[4];
        let __lane344_4 = __wide.lanes(__lane344)[4];
        let __lane289_4 = __wide.lanes(__lane289)[4];
        let __lane241_4 = __wide.lanes(__lane241)[4];
        let __lane212_4 = __wide.lanes(__lane212)[4];
        let __lane395_5 = __wide.lanes(__lane395)[5];
        let __lane388_5 = __wide.lanes(__lane388)[5];
        let __lane344_5 = __wide.lanes(__lane344)[5];
        let __lane289_5 = __wide.lanes(__lane289)[5];
        let __lane241_5 = __wide.lanes(__lane241)[5];
        let __lane212_5 = __wide.lanes(__lane212)[5];
        (
            ::planar_arm::__private::columns([
                [
                    __lane_zero,
                    __lane_zero,
                    __lane_zero,
                    __lane_zero,
                    __lane_zero,
                    __lane_zero,
                ],
                [
                    __lane411_0,
                    __lane411_1,
                    __lane411_2,
                    __lane411_3,
                    __lane411_4,
                    __lane411_5,
                ],
                [
                    __lane409_0,
                    __lane409_1,
                    __lane409_2,
                    __lane409_3,
                    __lane409_4,
                    __lane409_5,
                ],
                [
                    __lane406_0,
                    __lane406_1,
                    __lane406_2,
                    __lane406_3,
                    __lane406_4,
                    __lane406_5,
                ],
                [
                    __lane403_0,
                    __lane403_1,
                    __lane403_2,
                    __lane403_3,
                    __lane403_4,
                    __lane403_5,
                ],
                [
                    __lane400_0,
                    __lane400_1,
                    __lane400_2,
                    __lane400_3,
                    __lane400_4,
                    __lane400_5,
                ],
            ]),
            ::planar_arm::__private::columns([
                [
                    __lane395_0,
                    __lane395_1,
                    __lane395_2,
                    __lane395_3,
                    __lane395_4,
                    __lane395_5,
                ],
                [
                    __lane388_0,
                    __lane388_1,
                    __lane388_2,
                    __lane388_3,
                    __lane388_4,
                    __lane388_5,
                ],
                [
                    __lane344_0,
                    __lane344_1,
                    __lane344_2,
                    __lane344_3,
                    __lane344_4,
                    __lane344_5,
                ],
                [
                    __lane289_0,
                    __lane289_1,
                    __lane289_2,
                    __lane289_3,
                    __lane289_4,
                    __lane289_5,
                ],
                [
                    __lane241_0,
                    __lane241_1,
                    __lane241_2,
                    __lane241_3,
                    __lane241_4,
                    __lane241_5,
                ],
                [
                    __lane212_0,
                    __lane212_1,
                    __lane212_2,
                    __lane212_3,
                    __lane212_4,
                    __lane212_5,
                ],
            ]),
        )
    }
    /**The partial derivatives of `forward_dynamics`, `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, as Pinocchio's `computeABADerivatives`: `-M^-1 dtau/dq`, `-M^-1 dtau/dqd` at `qdd = forward_dynamics(q, qd, tau)`, and `M^-1`. NaN everywhere if M has no factor (only with NaN or infinite input).

In optimised x86-64 builds, where the processor has AVX2 and FMA: `M` and `h` (357 multiplications, 321 additions, 0 divisions, 5 sin_cos pairs), one `L D L^T` factor of M for `qdd` and `M^-1`, then the inverse dynamics run backward from the torques weighted by the rows of `-M^-1`: 200 multiplications, 160 additions, 0 divisions, 5 sin_cos pairs on scalars and 407 eight-lane operations (235 of them fused multiply-adds), one AVX-512 register per eight rows where the processor has AVX-512F (in a build with the default target flags), two AVX2 registers elsewhere. Other builds multiply `inverse_dynamics_derivatives` at `qdd` by `-M^-1`.*/
    #[inline]
    fn forward_dynamics_derivatives(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __tau: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> (
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
        ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 6>,
    ) {
        ::planar_arm::__private::dispatch_wide(::planar_arm::__private::ForwardDynamicsDerivatives::<
            Self,
            6,
        > {
            arm: self,
            q: __q,
            qd: __qd,
            tau: __tau,
        })
    }
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::spatial::SpatialArm<6> for Puma560 {
    /**The tool frame in the base frame: rotation R and position p.

```text
R11 = 1/16 cos(q1 - q2 - q3 - q4 - q5 - q6) + 1/16 cos(q1 - q2 - q3 - q4 - q5 + q6) + 1/8 cos(q1 - q2 - q3 - q4 - q6) - 1/8 cos(q1 - q2 - q3 - q4 + q6) + 1/16 cos(q1 - q2 - q3 - q4 + q5 - q6) + 1/16 cos(q1 - q2 - q3 - q4 + q5 + q6) + 1/8 cos(q1 - q2 - q3 - q5 - q6) + 1/8 cos(q1 - q2 - q3 - q5 + q6) - 1/8 cos(q1 - q2 - q3 + q5 - q6) - 1/8 cos(q1 - q2 - q3 + q5 + q6) + 1/16 cos(q1 - q2 - q3 + q4 - q5 - q6) + 1/16 cos(q1 - q2 - q3 + q4 - q5 + q6) - 1/8 cos(q1 - q2 - q3 + q4 - q6) + 1/8 cos(q1 - q2 - q3 + q4 + q6) + 1/16 cos(q1 - q2 - q3 + q4 + q5 - q6) + 1/16 cos(q1 - q2 - q3 + q4 + q5 + q6) - 1/8 cos(q1 - q4 - q5 - q6) - 1/8 cos(q1 - q4 - q5 + q6) - 1/4 cos(q1 - q4 - q6) + 1/4 cos(q1 - q4 + q6) - 1/8 cos(q1 - q4 + q5 - q6) - 1/8 cos(q1 - q4 + q5 + q6) + 1/8 cos(q1 + q4 - q5 - q6) + 1/8 cos(q1 + q4 - q5 + q6) - 1/4 cos(q1 + q4 - q6) + 1/4 cos(q1 + q4 + q6) + 1/8 cos(q1 + q4 + q5 - q6) + 1/8 cos(q1 + q4 + q5 + q6) + 1/16 cos(q1 + q2 + q3 - q4 - q5 - q6) + 1/16 cos(q1 + q2 + q3 - q4 - q5 + q6) + 1/8 cos(q1 + q2 + q3 - q4 - q6) - 1/8 cos(q1 + q2 + q3 - q4 + q6) + 1/16 cos(q1 + q2 + q3 - q4 + q5 - q6) + 1/16 cos(q1 + q2 + q3 - q4 + q5 + q6) - 1/8 cos(q1 + q2 + q3 - q5 - q6) - 1/8 cos(q1 + q2 + q3 - q5 + q6) + 1/8 cos(q1 + q2 + q3 + q5 - q6) + 1/8 cos(q1 + q2 + q3 + q5 + q6) + 1/16 cos(q1 + q2 + q3 + q4 - q5 - q6) + 1/16 cos(q1 + q2 + q3 + q4 - q5 + q6) - 1/8 cos(q1 + q2 + q3 + q4 - q6) + 1/8 cos(q1 + q2 + q3 + q4 + q6) + 1/16 cos(q1 + q2 + q3 + q4 + q5 - q6) + 1/16 c123456
R12 = 1/16 sin(q1 - q2 - q3 - q4 - q5 - q6) - 1/16 sin(q1 - q2 - q3 - q4 - q5 + q6) + 1/8 sin(q1 - q2 - q3 - q4 - q6) + 1/8 sin(q1 - q2 - q3 - q4 + q6) + 1/16 sin(q1 - q2 - q3 - q4 + q5 - q6) - 1/16 sin(q1 - q2 - q3 - q4 + q5 + q6) + 1/8 sin(q1 - q2 - q3 - q5 - q6) - 1/8 sin(q1 - q2 - q3 - q5 + q6) - 1/8 sin(q1 - q2 - q3 + q5 - q6) + 1/8 sin(q1 - q2 - q3 + q5 + q6) + 1/16 sin(q1 - q2 - q3 + q4 - q5 - q6) - 1/16 sin(q1 - q2 - q3 + q4 - q5 + q6) - 1/8 sin(q1 - q2 - q3 + q4 - q6) - 1/8 sin(q1 - q2 - q3 + q4 + q6) + 1/16 sin(q1 - q2 - q3 + q4 + q5 - q6) - 1/16 sin(q1 - q2 - q3 + q4 + q5 + q6) - 1/8 sin(q1 - q4 - q5 - q6) + 1/8 sin(q1 - q4 - q5 + q6) - 1/4 sin(q1 - q4 - q6) - 1/4 sin(q1 - q4 + q6) - 1/8 sin(q1 - q4 + q5 - q6) + 1/8 sin(q1 - q4 + q5 + q6) + 1/8 sin(q1 + q4 - q5 - q6) - 1/8 sin(q1 + q4 - q5 + q6) - 1/4 sin(q1 + q4 - q6) - 1/4 sin(q1 + q4 + q6) + 1/8 sin(q1 + q4 + q5 - q6) - 1/8 sin(q1 + q4 + q5 + q6) + 1/16 sin(q1 + q2 + q3 - q4 - q5 - q6) - 1/16 sin(q1 + q2 + q3 - q4 - q5 + q6) + 1/8 sin(q1 + q2 + q3 - q4 - q6) + 1/8 sin(q1 + q2 + q3 - q4 + q6) + 1/16 sin(q1 + q2 + q3 - q4 + q5 - q6) - 1/16 sin(q1 + q2 + q3 - q4 + q5 + q6) - 1/8 sin(q1 + q2 + q3 - q5 - q6) + 1/8 sin(q1 + q2 + q3 - q5 + q6) + 1/8 sin(q1 + q2 + q3 + q5 - q6) - 1/8 sin(q1 + q2 + q3 + q5 + q6) + 1/16 sin(q1 + q2 + q3 + q4 - q5 - q6) - 1/16 sin(q1 + q2 + q3 + q4 - q5 + q6) - 1/8 sin(q1 + q2 + q3 + q4 - q6) - 1/8 sin(q1 + q2 + q3 + q4 + q6) + 1/16 sin(q1 + q2 + q3 + q4 + q5 - q6) - 1/16 s123456
R13 = 1/8 sin(q1 - q2 - q3 - q4 - q5) - 1/8 sin(q1 - q2 - q3 - q4 + q5) + 1/4 sin(q1 - q2 - q3 - q5) + 1/4 sin(q1 - q2 - q3 + q5) + 1/8 sin(q1 - q2 - q3 + q4 - q5) - 1/8 sin(q1 - q2 - q3 + q4 + q5) - 1/4 sin(q1 - q4 - q5) + 1/4 sin(q1 - q4 + q5) + 1/4 sin(q1 + q4 - q5) - 1/4 sin(q1 + q4 + q5) + 1/8 sin(q1 + q2 + q3 - q4 - q5) - 1/8 sin(q1 + q2 + q3 - q4 + q5) - 1/4 sin(q1 + q2 + q3 - q5) - 1/4 sin(q1 + q2 + q3 + q5) + 1/8 sin(q1 + q2 + q3 + q4 - q5) - 1/8 s12345
p1 = 2159/10000 cos(q1 - q2) + 2159/10000 c12 + 203/20000 cos(q1 - q2 - q3) + 203/20000 c123 + 3001/20000 s1 + 2159/10000 sin(q1 - q2 - q3) - 2159/10000 s123
R21 = 1/16 sin(q1 - q2 - q3 - q4 - q5 - q6) + 1/16 sin(q1 - q2 - q3 - q4 - q5 + q6) + 1/8 sin(q1 - q2 - q3 - q4 - q6) - 1/8 sin(q1 - q2 - q3 - q4 + q6) + 1/16 sin(q1 - q2 - q3 - q4 + q5 - q6) + 1/16 sin(q1 - q2 - q3 - q4 + q5 + q6) + 1/8 sin(q1 - q2 - q3 - q5 - q6) + 1/8 sin(q1 - q2 - q3 - q5 + q6) - 1/8 sin(q1 - q2 - q3 + q5 - q6) - 1/8 sin(q1 - q2 - q3 + q5 + q6) + 1/16 sin(q1 - q2 - q3 + q4 - q5 - q6) + 1/16 sin(q1 - q2 - q3 + q4 - q5 + q6) - 1/8 sin(q1 - q2 - q3 + q4 - q6) + 1/8 sin(q1 - q2 - q3 + q4 + q6) + 1/16 sin(q1 - q2 - q3 + q4 + q5 - q6) + 1/16 sin(q1 - q2 - q3 + q4 + q5 + q6) - 1/8 sin(q1 - q4 - q5 - q6) - 1/8 sin(q1 - q4 - q5 + q6) - 1/4 sin(q1 - q4 - q6) + 1/4 sin(q1 - q4 + q6) - 1/8 sin(q1 - q4 + q5 - q6) - 1/8 sin(q1 - q4 + q5 + q6) + 1/8 sin(q1 + q4 - q5 - q6) + 1/8 sin(q1 + q4 - q5 + q6) - 1/4 sin(q1 + q4 - q6) + 1/4 sin(q1 + q4 + q6) + 1/8 sin(q1 + q4 + q5 - q6) + 1/8 sin(q1 + q4 + q5 + q6) + 1/16 sin(q1 + q2 + q3 - q4 - q5 - q6) + 1/16 sin(q1 + q2 + q3 - q4 - q5 + q6) + 1/8 sin(q1 + q2 + q3 - q4 - q6) - 1/8 sin(q1 + q2 + q3 - q4 + q6) + 1/16 sin(q1 + q2 + q3 - q4 + q5 - q6) + 1/16 sin(q1 + q2 + q3 - q4 + q5 + q6) - 1/8 sin(q1 + q2 + q3 - q5 - q6) - 1/8 sin(q1 + q2 + q3 - q5 + q6) + 1/8 sin(q1 + q2 + q3 + q5 - q6) + 1/8 sin(q1 + q2 + q3 + q5 + q6) + 1/16 sin(q1 + q2 + q3 + q4 - q5 - q6) + 1/16 sin(q1 + q2 + q3 + q4 - q5 + q6) - 1/8 sin(q1 + q2 + q3 + q4 - q6) + 1/8 sin(q1 + q2 + q3 + q4 + q6) + 1/16 sin(q1 + q2 + q3 + q4 + q5 - q6) + 1/16 s123456
R22 = -1/16 cos(q1 - q2 - q3 - q4 - q5 - q6) + 1/16 cos(q1 - q2 - q3 - q4 - q5 + q6) - 1/8 cos(q1 - q2 - q3 - q4 - q6) - 1/8 cos(q1 - q2 - q3 - q4 + q6) - 1/16 cos(q1 - q2 - q3 - q4 + q5 - q6) + 1/16 cos(q1 - q2 - q3 - q4 + q5 + q6) - 1/8 cos(q1 - q2 - q3 - q5 - q6) + 1/8 cos(q1 - q2 - q3 - q5 + q6) + 1/8 cos(q1 - q2 - q3 + q5 - q6) - 1/8 cos(q1 - q2 - q3 + q5 + q6) - 1/16 cos(q1 - q2 - q3 + q4 - q5 - q6) + 1/16 cos(q1 - q2 - q3 + q4 - q5 + q6) + 1/8 cos(q1 - q2 - q3 + q4 - q6) + 1/8 cos(q1 - q2 - q3 + q4 + q6) - 1/16 cos(q1 - q2 - q3 + q4 + q5 - q6) + 1/16 cos(q1 - q2 - q3 + q4 + q5 + q6) + 1/8 cos(q1 - q4 - q5 - q6) - 1/8 cos(q1 - q4 - q5 + q6) + 1/4 cos(q1 - q4 - q6) + 1/4 cos(q1 - q4 + q6) + 1/8 cos(q1 - q4 + q5 - q6) - 1/8 cos(q1 - q4 + q5 + q6) - 1/8 cos(q1 + q4 - q5 - q6) + 1/8 cos(q1 + q4 - q5 + q6) + 1/4 cos(q1 + q4 - q6) + 1/4 cos(q1 + q4 + q6) - 1/8 cos(q1 + q4 + q5 - q6) + 1/8 cos(q1 + q4 + q5 + q6) - 1/16 cos(q1 + q2 + q3 - q4 - q5 - q6) + 1/16 cos(q1 + q2 + q3 - q4 - q5 + q6) - 1/8 cos(q1 + q2 + q3 - q4 - q6) - 1/8 cos(q1 + q2 + q3 - q4 + q6) - 1/16 cos(q1 + q2 + q3 - q4 + q5 - q6) + 1/16 cos(q1 + q2 + q3 - q4 + q5 + q6) + 1/8 cos(q1 + q2 + q3 - q5 - q6) - 1/8 cos(q1 + q2 + q3 - q5 + q6) - 1/8 cos(q1 + q2 + q3 + q5 - q6) + 1/8 cos(q1 + q2 + q3 + q5 + q6) - 1/16 cos(q1 + q2 + q3 + q4 - q5 - q6) + 1/16 cos(q1 + q2 + q3 + q4 - q5 + q6) + 1/8 cos(q1 + q2 + q3 + q4 - q6) + 1/8 cos(q1 + q2 + q3 + q4 + q6) - 1/16 cos(q1 + q2 + q3 + q4 + q5 - q6) + 1/16 c123456
R23 = -1/8 cos(q1 - q2 - q3 - q4 - q5) + 1/8 cos(q1 - q2 - q3 - q4 + q5) - 1/4 cos(q1 - q2 - q3 - q5) - 1/4 cos(q1 - q2 - q3 + q5) - 1/8 cos(q1 - q2 - q3 + q4 - q5) + 1/8 cos(q1 - q2 - q3 + q4 + q5) + 1/4 cos(q1 - q4 - q5) - 1/4 cos(q1 - q4 + q5) - 1/4 cos(q1 + q4 - q5) + 1/4 cos(q1 + q4 + q5) - 1/8 cos(q1 + q2 + q3 - q4 - q5) + 1/8 cos(q1 + q2 + q3 - q4 + q5) + 1/4 cos(q1 + q2 + q3 - q5) + 1/4 cos(q1 + q2 + q3 + q5) - 1/8 cos(q1 + q2 + q3 + q4 - q5) + 1/8 c12345
p2 = -3001/20000 c1 - 2159/10000 cos(q1 - q2 - q3) + 2159/10000 c123 + 2159/10000 sin(q1 - q2) + 2159/10000 s12 + 203/20000 sin(q1 - q2 - q3) + 203/20000 s123
R31 = 1/8 sin(q2 + q3 - q4 - q5 - q6) + 1/8 sin(q2 + q3 - q4 - q5 + q6) + 1/4 sin(q2 + q3 - q4 - q6) - 1/4 sin(q2 + q3 - q4 + q6) + 1/8 sin(q2 + q3 - q4 + q5 - q6) + 1/8 sin(q2 + q3 - q4 + q5 + q6) - 1/4 sin(q2 + q3 - q5 - q6) - 1/4 sin(q2 + q3 - q5 + q6) + 1/4 sin(q2 + q3 + q5 - q6) + 1/4 sin(q2 + q3 + q5 + q6) + 1/8 sin(q2 + q3 + q4 - q5 - q6) + 1/8 sin(q2 + q3 + q4 - q5 + q6) - 1/4 sin(q2 + q3 + q4 - q6) + 1/4 sin(q2 + q3 + q4 + q6) + 1/8 sin(q2 + q3 + q4 + q5 - q6) + 1/8 s23456
R32 = -1/8 cos(q2 + q3 - q4 - q5 - q6) + 1/8 cos(q2 + q3 - q4 - q5 + q6) - 1/4 cos(q2 + q3 - q4 - q6) - 1/4 cos(q2 + q3 - q4 + q6) - 1/8 cos(q2 + q3 - q4 + q5 - q6) + 1/8 cos(q2 + q3 - q4 + q5 + q6) + 1/4 cos(q2 + q3 - q5 - q6) - 1/4 cos(q2 + q3 - q5 + q6) - 1/4 cos(q2 + q3 + q5 - q6) + 1/4 cos(q2 + q3 + q5 + q6) - 1/8 cos(q2 + q3 + q4 - q5 - q6) + 1/8 cos(q2 + q3 + q4 - q5 + q6) + 1/4 cos(q2 + q3 + q4 - q6) + 1/4 cos(q2 + q3 + q4 + q6) - 1/8 cos(q2 + q3 + q4 + q5 - q6) + 1/8 c23456
R33 = -1/4 cos(q2 + q3 - q4 - q5) + 1/4 cos(q2 + q3 - q4 + q5) + 1/2 cos(q2 + q3 - q5) + 1/2 cos(q2 + q3 + q5) - 1/4 cos(q2 + q3 + q4 - q5) + 1/4 c2345
p3 = 2159/5000 c23 + 2159/5000 s2 + 203/10000 s23
```


the joints' transformations multiplied out base to tip

Cost: 61 multiplications, 37 additions, 0 divisions, 6 sin_cos pairs.*/
    #[inline]
    fn tip_pose(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> ::planar_arm::nalgebra::Isometry3<::core::primitive::f64> {
        let _ = (
            &self.waist,
            &self.shoulder,
            &self.elbow,
            &self.wrist1,
            &self.wrist2,
            &self.wrist3,
        );
        let [__q1, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5),
        (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s1;
        let __t2 = -__s2;
        let __t3 = __c1 * __c2;
        let __t4 = __c1 * __t2;
        let __t5 = __s1 * __c2;
        let __t6 = __s1 * __t2;
        let __t7 = -__s3;
        let __t8 = __t3 * __c3 + __t4 * __s3;
        let __t9 = __t3 * __t7 + __t4 * __c3;
        let __t10 = __t5 * __c3 + __t6 * __s3;
        let __t11 = __t5 * __t7 + __t6 * __c3;
        let __t12 = __s2 * __c3 + __c2 * __s3;
        let __t13 = __s2 * __t7 + __c2 * __c3;
        let __t14 = -__s4;
        let __t15 = __t8 * __c4 + __t1 * __s4;
        let __t16 = __t8 * __t14 + __t1 * __c4;
        let __t17 = __t10 * __c4 + __c1 * __s4;
        let __t18 = __t10 * __t14 + __c1 * __c4;
        let __t19 = __t12 * __c4;
        let __t20 = __t12 * __t14;
        let __p1 = (2159.0 / 5000.0) * __t3 + (203.0 / 10000.0) * __t8
            + (3001.0 / 20000.0) * __s1 + (2159.0 / 5000.0) * __t9;
        let __p2 = (2159.0 / 5000.0) * __t5 + (203.0 / 10000.0) * __t10
            + (3001.0 / 20000.0) * (-__c1) + (2159.0 / 5000.0) * __t11;
        let __p3 = (2159.0 / 5000.0) * __s2 + (203.0 / 10000.0) * __t12
            + (2159.0 / 5000.0) * __t13;
        let __t21 = -__s5;
        let __t22 = __t15 * __c5 + __t9 * __s5;
        let __r13 = __t15 * __t21 + __t9 * __c5;
        let __t23 = __t17 * __c5 + __t11 * __s5;
        let __r23 = __t17 * __t21 + __t11 * __c5;
        let __t24 = __t19 * __c5 + __t13 * __s5;
        let __r33 = __t19 * __t21 + __t13 * __c5;
        let __t25 = -__s6;
        let __r11 = __t22 * __c6 + __t16 * __s6;
        let __r12 = __t22 * __t25 + __t16 * __c6;
        let __r21 = __t23 * __c6 + __t18 * __s6;
        let __r22 = __t23 * __t25 + __t18 * __c6;
        let __r31 = __t24 * __c6 + __t20 * __s6;
        let __r32 = __t24 * __t25 + __t20 * __c6;
        ::planar_arm::__private::isometry3(
            [[__r11, __r12, __r13], [__r21, __r22, __r23], [__r31, __r32, __r33]],
            [__p1, __p2, __p3],
        )
    }
    /**Each link's frame in the base frame, base first.

the joints' transformations multiplied out base to tip

Cost: 61 multiplications, 40 additions, 0 divisions, 6 sin_cos pairs.*/
    #[inline]
    fn link_poses(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> [::planar_arm::nalgebra::Isometry3<::core::primitive::f64>; 6] {
        let [__q1, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5),
        (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __l3r12 = -__s1;
        let __l1r23 = -__c1;
        let __t1 = -__s2;
        let __l2r11 = __c1 * __c2;
        let __l2r12 = __c1 * __t1;
        let __l2r21 = __s1 * __c2;
        let __l2r22 = __s1 * __t1;
        let __l2p1 = (2159.0 / 5000.0) * __l2r11;
        let __l2p2 = (2159.0 / 5000.0) * __l2r21;
        let __l2p3 = (2159.0 / 5000.0) * __s2;
        let __t2 = -__s3;
        let __l3r11 = __l2r11 * __c3 + __l2r12 * __s3;
        let __l3r13 = __l2r11 * __t2 + __l2r12 * __c3;
        let __l3r21 = __l2r21 * __c3 + __l2r22 * __s3;
        let __l3r23 = __l2r21 * __t2 + __l2r22 * __c3;
        let __l3r31 = __s2 * __c3 + __c2 * __s3;
        let __l3r33 = __s2 * __t2 + __c2 * __c3;
        let __l3p1 = __l2p1 + (203.0 / 10000.0) * __l3r11 + (3001.0 / 20000.0) * __s1;
        let __l3p2 = __l2p2 + (203.0 / 10000.0) * __l3r21 + (3001.0 / 20000.0) * __l1r23;
        let __l3p3 = __l2p3 + (203.0 / 10000.0) * __l3r31;
        let __t3 = -__s4;
        let __l4r11 = __l3r11 * __c4 + __l3r12 * __s4;
        let __l5r12 = __l3r11 * __t3 + __l3r12 * __c4;
        let __l4r21 = __l3r21 * __c4 + __c1 * __s4;
        let __l5r22 = __l3r21 * __t3 + __c1 * __c4;
        let __l4r31 = __l3r31 * __c4;
        let __l5r32 = __l3r31 * __t3;
        let __l4r13 = -__l5r12;
        let __l4r23 = -__l5r22;
        let __l4r33 = -__l5r32;
        let __l4p1 = __l3p1 + (2159.0 / 5000.0) * __l3r13;
        let __l4p2 = __l3p2 + (2159.0 / 5000.0) * __l3r23;
        let __l4p3 = __l3p3 + (2159.0 / 5000.0) * __l3r33;
        let __t4 = -__s5;
        let __l5r11 = __l4r11 * __c5 + __l3r13 * __s5;
        let __l5r13 = __l4r11 * __t4 + __l3r13 * __c5;
        let __l5r21 = __l4r21 * __c5 + __l3r23 * __s5;
        let __l5r23 = __l4r21 * __t4 + __l3r23 * __c5;
        let __l5r31 = __l4r31 * __c5 + __l3r33 * __s5;
        let __l5r33 = __l4r31 * __t4 + __l3r33 * __c5;
        let __t5 = -__s6;
        let __l6r11 = __l5r11 * __c6 + __l5r12 * __s6;
        let __l6r12 = __l5r11 * __t5 + __l5r12 * __c6;
        let __l6r21 = __l5r21 * __c6 + __l5r22 * __s6;
        let __l6r22 = __l5r21 * __t5 + __l5r22 * __c6;
        let __l6r31 = __l5r31 * __c6 + __l5r32 * __s6;
        let __l6r32 = __l5r31 * __t5 + __l5r32 * __c6;
        let __l1r12 = 0.0;
        let __l1r32 = 1.0;
        [
            ::planar_arm::__private::isometry3(
                [
                    [__c1, __l1r12, __s1],
                    [__s1, __l1r12, __l1r23],
                    [__l1r12, __l1r32, __l1r12],
                ],
                [__l1r12, __l1r12, __l1r12],
            ),
            ::planar_arm::__private::isometry3(
                [
                    [__l2r11, __l2r12, __s1],
                    [__l2r21, __l2r22, __l1r23],
                    [__s2, __c2, __l1r12],
                ],
                [__l2p1, __l2p2, __l2p3],
            ),
            ::planar_arm::__private::isometry3(
                [
                    [__l3r11, __l3r12, __l3r13],
                    [__l3r21, __c1, __l3r23],
                    [__l3r31, __l1r12, __l3r33],
                ],
                [__l3p1, __l3p2, __l3p3],
            ),
            ::planar_arm::__private::isometry3(
                [
                    [__l4r11, __l3r13, __l4r13],
                    [__l4r21, __l3r23, __l4r23],
                    [__l4r31, __l3r33, __l4r33],
                ],
                [__l4p1, __l4p2, __l4p3],
            ),
            ::planar_arm::__private::isometry3(
                [
                    [__l5r11, __l5r12, __l5r13],
                    [__l5r21, __l5r22, __l5r23],
                    [__l5r31, __l5r32, __l5r33],
                ],
                [__l4p1, __l4p2, __l4p3],
            ),
            ::planar_arm::__private::isometry3(
                [
                    [__l6r11, __l6r12, __l5r13],
                    [__l6r21, __l6r22, __l5r23],
                    [__l6r31, __l6r32, __l5r33],
                ],
                [__l4p1, __l4p2, __l4p3],
            ),
        ]
    }
    /**The geometric Jacobian of the tool frame: rows 0-2 the linear velocity of its origin, rows 3-5 the angular velocity, both in base coordinates (Pinocchio's `LOCAL_WORLD_ALIGNED`).

each joint's axis from the product of transformations, crossed with the arm to the tool origin

Cost: 57 multiplications, 44 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn jacobian<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> ::planar_arm::nalgebra::SMatrix<__T, 6, 6> {
        let [__q1, __q2, __q3, __q4, __q5, _] = ::planar_arm::__private::unpack(__q);
        let [(__s1, __c1), (__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5)] = ::planar_arm::__private::sin_cos([
            __q1,
            __q2,
            __q3,
            __q4,
            __q5,
        ]);
        let __t1 = -__s1;
        let __j52 = -__c1;
        let __t2 = -__s2;
        let __t3 = __c1 * __c2;
        let __t4 = __c1 * __t2;
        let __t5 = __s1 * __c2;
        let __t6 = __s1 * __t2;
        let __t7 = __T::from_f64(2159.0 / 5000.0) * __t3;
        let __t8 = __T::from_f64(2159.0 / 5000.0) * __t5;
        let __t9 = __T::from_f64(2159.0 / 5000.0) * __s2;
        let __t10 = -__s3;
        let __t11 = __t3 * __c3 + __t4 * __s3;
        let __j44 = __t3 * __t10 + __t4 * __c3;
        let __t12 = __t5 * __c3 + __t6 * __s3;
        let __j54 = __t5 * __t10 + __t6 * __c3;
        let __t13 = __s2 * __c3 + __c2 * __s3;
        let __j64 = __s2 * __t10 + __c2 * __c3;
        let __t14 = __t7 + __T::from_f64(203.0 / 10000.0) * __t11
            + __T::from_f64(3001.0 / 20000.0) * __s1;
        let __t15 = __t8 + __T::from_f64(203.0 / 10000.0) * __t12
            + __T::from_f64(3001.0 / 20000.0) * __j52;
        let __t16 = __t9 + __T::from_f64(203.0 / 10000.0) * __t13;
        let __t17 = -__s4;
        let __j45 = -(__t11 * __t17 + __t1 * __c4);
        let __j55 = -(__t12 * __t17 + __c1 * __c4);
        let __j65 = -(__t13 * __t17);
        let __j21 = __t14 + __T::from_f64(2159.0 / 5000.0) * __j44;
        let __t18 = __t15 + __T::from_f64(2159.0 / 5000.0) * __j54;
        let __t19 = __t16 + __T::from_f64(2159.0 / 5000.0) * __j64;
        let __t20 = -__s5;
        let __j46 = (__t11 * __c4 + __t1 * __s4) * __t20 + __j44 * __c5;
        let __j56 = (__t12 * __c4 + __c1 * __s4) * __t20 + __j54 * __c5;
        let __j66 = __t13 * __c4 * __t20 + __j64 * __c5;
        let __j11 = -__t18;
        let __j12 = __j52 * __t19;
        let __j22 = -(__s1 * __t19);
        let __j32 = __s1 * __t18 - __j52 * __j21;
        let __t21 = __t19 - __t9;
        let __j13 = __j52 * __t21;
        let __j23 = -(__s1 * __t21);
        let __j33 = __s1 * (__t18 - __t8) - __j52 * (__j21 - __t7);
        let __t22 = __j21 - __t14;
        let __t23 = __t18 - __t15;
        let __t24 = __t19 - __t16;
        let __j14 = __j54 * __t24 - __j64 * __t23;
        let __j24 = __j64 * __t22 - __j44 * __t24;
        let __j34 = __j44 * __t23 - __j54 * __t22;
        let __j15 = __T::from_f64(0.0);
        let __j61 = __T::from_f64(1.0);
        ::planar_arm::__private::columns([
            [__j11, __j21, __j15, __j15, __j15, __j61],
            [__j12, __j22, __j32, __s1, __j52, __j15],
            [__j13, __j23, __j33, __s1, __j52, __j15],
            [__j14, __j24, __j34, __j44, __j54, __j64],
            [__j15, __j15, __j15, __j45, __j55, __j65],
            [__j15, __j15, __j15, __j46, __j56, __j66],
        ])
    }
    const EXACT: ::planar_arm::exact::SpatialDerivation<6> = {
        const __NAMES: &[&::core::primitive::str] = &[];
        ::planar_arm::exact::SpatialDerivation {
            expansion: ::core::option::Option::Some(::planar_arm::exact::SpatialExpansion {
                tip: [
                    [
                        ::planar_arm::__private::terms(
                            b"BCgBGCABCAFBAABCgBGDABCAEBABCAABCQGDABCADBBBBAABBQGDABCADBBBCAABCgBGEABCADBABCABBAABCgBGDABCADBACCAABCQGDABCACBBCBAABCQGEABCACBBBBABCAABBQGEABCACBBBCABBAABBQGDABCACBBCCAABCgBGEABCACBABCACBAABCgBGFABCACBABCABBABCAABBQGEABCACBABCBBBAABCQGEABCACBABCBBCAABCgBGEABCACBACCABBAABCgBGDABCACBADCAABBQGCABCCDBAABBQGDABCCCBABCAABBIGDABCCBBBBBAABCIGDABCCBBBBCAABBQGEABCCBBABCABBAABBQGDABCCBBACCAABCQGDABCCBCACBAABCQGEABCCBCABBABCAABBIGDABCCBCBBBAABCIGDABCCBCBBCAABCQGDABCCCCABBAABCQGCABCCDCAABCgBGCADCADBAABCgBGDADCACBABCAABCQGDADCABBBBBAABBQGDADCABBBBCAABCgBGEADCABBABCABBAABCgBGDADCABBACCAABBQGCADCBCBAABBQGDADCBBBABCAABCQGDADCBBCABBAABCQGCADCBCCAABCgBGCAECACBAABCgBGDAECABBABCAABBQGCAECBBBAABCQGCAECBBCAABCgBGCAFCABBAABCgBGBAGCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"CCgBGCABCAFBAACBgBGDABCAEBABCAACCQGDABCADBBBBAACCQGDABCADBBBCAACCgBGEABCADBABCABBAACBgBGDABCADBACCAACCQGDABCACBBCBAACBQGEABCACBBBBABCAACBQGEABCACBBBCABBAACCQGDABCACBBCCAACCgBGEABCACBABCACBAACBgBGFABCACBABCABBABCAACBQGEABCACBABCBBBAACBQGEABCACBABCBBCAACCgBGEABCACBACCABBAACBgBGDABCACBADCAACBQGCABCCDBAACCQGDABCCCBABCAACBIGDABCCBBBBBAACBIGDABCCBBBBCAACBQGEABCCBBABCABBAACCQGDABCCBBACCAACCQGDABCCBCACBAACBQGEABCCBCABBABCAACBIGDABCCBCBBBAACBIGDABCCBCBBCAACCQGDABCCCCABBAACBQGCABCCDCAACCgBGCADCADBAACBgBGDADCACBABCAACCQGDADCABBBBBAACCQGDADCABBBBCAACCgBGEADCABBABCABBAACBgBGDADCABBACCAACBQGCADCBCBAACCQGDADCBBBABCAACCQGDADCBBCABBAACBQGCADCBCCAACCgBGCAECACBAACBgBGDAECABBABCAACBQGCAECBBBAACBQGCAECBBCAACCgBGCAFCABBAACBgBGBAGCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"CCQFCABCAEBAACBQFDABCADBABCAACCIFDABCACBBBBAACCIFDABCACBBBCAACCQFEABCACBABCABBAACBQFDABCACBACCAACBIFCABCCCBAACCIFDABCCBBABCAACCIFDABCCBCABBAACBIFCABCCCCAACCQFCADCACBAACBQFDADCABBABCAACBIFCADCBBBAACBIFCADCBBCAACCQFCAECABBAACBQFBAFCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"B+mEgxTCCABCABBAAB+mEgxTCBACCAAB2MginBDCABCACBAAB2MginBDBADCAACy7FginBBBABCAAC+mEgxTDCABCACBAAC9mEgxTDBADCAA",
                            __NAMES,
                        ),
                    ],
                    [
                        ::planar_arm::__private::terms(
                            b"CCgBGCABCAFBAACCgBGDABCAEBABCAACCQGDABCADBBBBAACBQGDABCADBBBCAACCgBGEABCADBABCABBAACCgBGDABCADBACCAACCQGDABCACBBCBAACCQGEABCACBBBBABCAACBQGEABCACBBBCABBAACBQGDABCACBBCCAACCgBGEABCACBABCACBAACCgBGFABCACBABCABBABCAACBQGEABCACBABCBBBAACCQGEABCACBABCBBCAACCgBGEABCACBACCABBAACCgBGDABCACBADCAACBQGCABCCDBAACBQGDABCCCBABCAACBIGDABCCBBBBBAACCIGDABCCBBBBCAACBQGEABCCBBABCABBAACBQGDABCCBBACCAACCQGDABCCBCACBAACCQGEABCCBCABBABCAACBIGDABCCBCBBBAACCIGDABCCBCBBCAACCQGDABCCCCABBAACCQGCABCCDCAACCgBGCADCADBAACCgBGDADCACBABCAACCQGDADCABBBBBAACBQGDADCABBBBCAACCgBGEADCABBABCABBAACCgBGDADCABBACCAACBQGCADCBCBAACBQGDADCBBBABCAACCQGDADCBBCABBAACCQGCADCBCCAACCgBGCAECACBAACCgBGDAECABBABCAACBQGCAECBBBAACCQGCAECBBCAACCgBGCAFCABBAACCgBGBAGCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"BBgBGCABCAFBAABCgBGDABCAEBABCAABBQGDABCADBBBBAABBQGDABCADBBBCAABBgBGEABCADBABCABBAABCgBGDABCADBACCAABBQGDABCACBBCBAABCQGEABCACBBBBABCAABCQGEABCACBBBCABBAABBQGDABCACBBCCAABBgBGEABCACBABCACBAABCgBGFABCACBABCABBABCAABCQGEABCACBABCBBBAABCQGEABCACBABCBBCAABBgBGEABCACBACCABBAABCgBGDABCACBADCAABCQGCABCCDBAABBQGDABCCCBABCAABCIGDABCCBBBBBAABCIGDABCCBBBBCAABCQGEABCCBBABCABBAABBQGDABCCBBACCAABBQGDABCCBCACBAABCQGEABCCBCABBABCAABCIGDABCCBCBBBAABCIGDABCCBCBBCAABBQGDABCCCCABBAABCQGCABCCDCAABBgBGCADCADBAABCgBGDADCACBABCAABBQGDADCABBBBBAABBQGDADCABBBBCAABBgBGEADCABBABCABBAABCgBGDADCABBACCAABCQGCADCBCBAABBQGDADCBBBABCAABBQGDADCBBCABBAABCQGCADCBCCAABBgBGCAECACBAABCgBGDAECABBABCAABCQGCAECBBBAABCQGCAECBBCAABBgBGCAFCABBAABCgBGBAGCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"BBQFCABCAEBAABCQFDABCADBABCAABBIFDABCACBBBBAABBIFDABCACBBBCAABBQFEABCACBABCABBAABCQFDABCACBACCAABCIFCABCCCBAABBIFDABCCBBABCAABBIFDABCCBCABBAABCIFCABCCCCAABBQFCADCACBAABCQFDADCABBABCAABCIFCADCBBBAABCIFCADCBBCAABBQFCAECABBAABCQFBAFCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"Bx7FginBBBABCAAB9mEgxTDCABCACBAAB+mEgxTDBADCAAC+mEgxTCCABCABBAAC+mEgxTCBACCAAC2MginBDCABCACBAAC2MginBDBADCAA",
                            __NAMES,
                        ),
                    ],
                    [
                        ::planar_arm::__private::terms(
                            b"CCQGCBCCADBAACCQGDBCCACBABCAACCIGDBCCABBBBBAACBIGDBCCABBBBCAACCQGEBCCABBABCABBAACCQGDBCCABBACCAACBIGCBCCBCBAACBIGDBCCBBBABCAACCIGDBCCBBCABBAACCIGCBCCBCCAACCQGCBDCACBAACCQGDBDCABBABCAACBIGCBDCBBBAACCIGCBDCBBCAACCQGCBECABBAACCQGBBFCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"BBQGCBCCADBAABCQGDBCCACBABCAABBIGDBCCABBBBBAABBIGDBCCABBBBCAABBQGEBCCABBABCABBAABCQGDBCCABBACCAABCIGCBCCBCBAABBIGDBCCBBBABCAABBIGDBCCBBCABBAABCIGCBCCBCCAABBQGCBDCACBAABCQGDBDCABBABCAABCIGCBDCBBBAABCIGCBDCBBCAABBQGCBECABBAABCQGBBFCAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"BBIFCBCCACBAABCIFDBCCABBABCAABCEFCBCCBBBAABCEFCBCCBBCAABBIFCBDCABBAABCIFBBECAA",
                            __NAMES,
                        ),
                        ::planar_arm::__private::terms(
                            b"B+mEw4JDBBCCAAC+mEw4JCBBBCAAC2MgxTDBBCCAA",
                            __NAMES,
                        ),
                    ],
                ],
                potential_energy: ::planar_arm::__private::terms(
                    b"Byi0PgpoPCBBBCAABin84mFgoriTDBBCCAAB5nRgtpsCFCBCCACBAAB6nRgtpsCFDBCCABBABCAAB6nRw2kmBFCBCCBBBAAB6nRw2kmBFCBCCBBCAAB5nRgtpsCFCBDCABBAAB6nRgtpsCFBBECAACm/ommWgoriTCBBBCAACu+kMgw6wBDBBCCAA",
                    __NAMES,
                ),
                gravity: [
                    ::planar_arm::__private::terms(b"", __NAMES),
                    ::planar_arm::__private::terms(
                        b"Bm/ommWgoriTCBBBCAABu+kMgw6wBDBBCCAACxi0PgpoPCBBBCAAChn84mFgoriTDBBCCAAC6nRgtpsCFCBCCACBAAC5nRgtpsCFDBCCABBABCAAC5nRw2kmBFCBCCBBBAAC5nRw2kmBFCBCCBBCAAC6nRgtpsCFCBDCABBAAC5nRgtpsCFBBECAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(
                        b"Bu+kMgw6wBDBBCCAAChn84mFgoriTDBBCCAAC6nRgtpsCFCBCCACBAAC5nRgtpsCFDBCCABBABCAAC5nRw2kmBFCBCCBBBAAC5nRw2kmBFCBCCBBCAAC6nRgtpsCFCBDCABBAAC5nRgtpsCFBBECAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(
                        b"C5nRgtpsCFCBCCACBAAC6nRgtpsCFDBCCABBABCAAC6nRgtpsCFCBDCABBAAC5nRgtpsCFBBECAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(
                        b"C5nRgtpsCFCBCCACBAAC5nRgtpsCFDBCCABBABCAAC6nRw2kmBFCBCCBBBAAC5nRw2kmBFCBCCBBCAAC5nRgtpsCFCBDCABBAAC5nRgtpsCFBBECAA",
                        __NAMES,
                    ),
                    ::planar_arm::__private::terms(b"", __NAMES),
                ],
                mass_matrix: ::core::option::Option::None,
                coriolis: ::core::option::Option::None,
            }),
        }
    };
    ///The joints' names, base first: the order of `q`.
    const JOINT_NAMES: [&'static ::core::primitive::str; 6] = [
        "waist",
        "shoulder",
        "elbow",
        "wrist1",
        "wrist2",
        "wrist3",
    ];
    #[inline]
    fn model(&self) -> ::planar_arm::spatial::SpatialModel<6> {
        ::planar_arm::spatial::SpatialModel {
            joints: [
                ::planar_arm::spatial::SpatialJoint {
                    geometry: ::planar_arm::spatial::JointGeometry::Dh {
                        a: 0.0,
                        alpha: ::core::f64::consts::FRAC_PI_2,
                        d: 0.0,
                        theta: 0.0,
                    },
                    kind: ::planar_arm::Joint::Revolute,
                    range: ::core::option::Option::None,
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    stiffness: 0.0,
                    springref: 0.0,
                },
                ::planar_arm::spatial::SpatialJoint {
                    geometry: ::planar_arm::spatial::JointGeometry::Dh {
                        a: (2159.0 / 5000.0),
                        alpha: 0.0,
                        d: 0.0,
                        theta: 0.0,
                    },
                    kind: ::planar_arm::Joint::Revolute,
                    range: ::core::option::Option::None,
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    stiffness: 0.0,
                    springref: 0.0,
                },
                ::planar_arm::spatial::SpatialJoint {
                    geometry: ::planar_arm::spatial::JointGeometry::Dh {
                        a: (203.0 / 10000.0),
                        alpha: (-::core::f64::consts::FRAC_PI_2),
                        d: (3001.0 / 20000.0),
                        theta: 0.0,
                    },
                    kind: ::planar_arm::Joint::Revolute,
                    range: ::core::option::Option::None,
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    stiffness: 0.0,
                    springref: 0.0,
                },
                ::planar_arm::spatial::SpatialJoint {
                    geometry: ::planar_arm::spatial::JointGeometry::Dh {
                        a: 0.0,
                        alpha: ::core::f64::consts::FRAC_PI_2,
                        d: (2159.0 / 5000.0),
                        theta: 0.0,
                    },
                    kind: ::planar_arm::Joint::Revolute,
                    range: ::core::option::Option::None,
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    stiffness: 0.0,
                    springref: 0.0,
                },
                ::planar_arm::spatial::SpatialJoint {
                    geometry: ::planar_arm::spatial::JointGeometry::Dh {
                        a: 0.0,
                        alpha: (-::core::f64::consts::FRAC_PI_2),
                        d: 0.0,
                        theta: 0.0,
                    },
                    kind: ::planar_arm::Joint::Revolute,
                    range: ::core::option::Option::None,
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    stiffness: 0.0,
                    springref: 0.0,
                },
                ::planar_arm::spatial::SpatialJoint {
                    geometry: ::planar_arm::spatial::JointGeometry::Dh {
                        a: 0.0,
                        alpha: 0.0,
                        d: 0.0,
                        theta: 0.0,
                    },
                    kind: ::planar_arm::Joint::Revolute,
                    range: ::core::option::Option::None,
                    armature: 0.0,
                    damping: 0.0,
                    frictionloss: 0.0,
                    stiffness: 0.0,
                    springref: 0.0,
                },
            ],
            links: [
                ::planar_arm::spatial::SpatialLink {
                    mass: 0.0,
                    com: ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 0.0),
                    inertia: ::planar_arm::nalgebra::Matrix3::new(
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                    ),
                },
                ::planar_arm::spatial::SpatialLink {
                    mass: (87.0 / 5.0),
                    com: ::planar_arm::nalgebra::Vector3::new(
                        (-(1819.0 / 5000.0)),
                        (3.0 / 500.0),
                        (91.0 / 400.0),
                    ),
                    inertia: ::planar_arm::nalgebra::Matrix3::new(
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                    ),
                },
                ::planar_arm::spatial::SpatialLink {
                    mass: (24.0 / 5.0),
                    com: ::planar_arm::nalgebra::Vector3::new(
                        (-(203.0 / 10000.0)),
                        (-(141.0 / 10000.0)),
                        (7.0 / 100.0),
                    ),
                    inertia: ::planar_arm::nalgebra::Matrix3::new(
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                    ),
                },
                ::planar_arm::spatial::SpatialLink {
                    mass: (41.0 / 50.0),
                    com: ::planar_arm::nalgebra::Vector3::new(0.0, (19.0 / 1000.0), 0.0),
                    inertia: ::planar_arm::nalgebra::Matrix3::new(
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                    ),
                },
                ::planar_arm::spatial::SpatialLink {
                    mass: (17.0 / 50.0),
                    com: ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 0.0),
                    inertia: ::planar_arm::nalgebra::Matrix3::new(
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                    ),
                },
                ::planar_arm::spatial::SpatialLink {
                    mass: (9.0 / 100.0),
                    com: ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, (4.0 / 125.0)),
                    inertia: ::planar_arm::nalgebra::Matrix3::new(
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                        0.0,
                    ),
                },
            ],
            gravity: ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, (-(981.0 / 100.0))),
            tool: ::planar_arm::nalgebra::Isometry3::from_parts(
                ::planar_arm::nalgebra::Translation3::from(
                    ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 0.0),
                ),
                ::planar_arm::nalgebra::UnitQuaternion::from_euler_angles(0.0, 0.0, 0.0),
            ),
            payload: ::core::option::Option::None,
        }
    }
    ///Every solution in closed form (a spherical wrist, axes 2 and 3 parallel: decided at compile time from the exact geometry); see `planar_arm::spatial::SpatialIk`.
    #[inline]
    fn inverse_kinematics(
        &self,
        __target: &::planar_arm::nalgebra::Isometry3<::core::primitive::f64>,
    ) -> ::core::result::Result<
        ::planar_arm::spatial::IkSolutions<6>,
        ::planar_arm::ArmError,
    > {
        let ik = ::planar_arm::spatial::SpatialIk {
            class: ::planar_arm::spatial::IkClass::SphericalWrist,
            points: [
                ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 0.0),
                ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 0.0),
                ::planar_arm::nalgebra::Vector3::new(0.4318, 0.0, 0.0),
                ::planar_arm::nalgebra::Vector3::new(0.4521, (-0.15005), 0.0),
                ::planar_arm::nalgebra::Vector3::new(0.4521, (-0.15005), 0.4318),
                ::planar_arm::nalgebra::Vector3::new(0.4521, (-0.15005), 0.4318),
            ],
            axes: [
                ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 1.0),
                ::planar_arm::nalgebra::Vector3::new(0.0, (-1.0), 0.0),
                ::planar_arm::nalgebra::Vector3::new(0.0, (-1.0), 0.0),
                ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 1.0),
                ::planar_arm::nalgebra::Vector3::new(0.0, (-1.0), 0.0),
                ::planar_arm::nalgebra::Vector3::new(0.0, 0.0, 1.0),
            ],
            home: ::planar_arm::__private::isometry3(
                [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
                [0.4521, (-0.15005), 0.4318],
            ),
            centre: ::planar_arm::nalgebra::Vector3::new(0.4521, (-0.15005), 0.4318),
            scale: 0.642931296873935,
        };
        ik.solve(
            __target,
            &[
                ::core::option::Option::None,
                ::core::option::Option::None,
                ::core::option::Option::None,
                ::core::option::Option::None,
                ::core::option::Option::None,
                ::core::option::Option::None,
            ],
        )
    }
}
#[automatically_derived]
#[allow(clippy::nursery, clippy::approx_constant)]
impl ::planar_arm::Identification<6, 60, 36> for Puma560 {
    const PARAMETERS: [&'static ::core::primitive::str; 60] = [
        "m1",
        "mx1",
        "my1",
        "mz1",
        "xx1",
        "xy1",
        "yy1",
        "xz1",
        "yz1",
        "zz1",
        "m2",
        "mx2",
        "my2",
        "mz2",
        "xx2",
        "xy2",
        "yy2",
        "xz2",
        "yz2",
        "zz2",
        "m3",
        "mx3",
        "my3",
        "mz3",
        "xx3",
        "xy3",
        "yy3",
        "xz3",
        "yz3",
        "zz3",
        "m4",
        "mx4",
        "my4",
        "mz4",
        "xx4",
        "xy4",
        "yy4",
        "xz4",
        "yz4",
        "zz4",
        "m5",
        "mx5",
        "my5",
        "mz5",
        "xx5",
        "xy5",
        "yy5",
        "xz5",
        "yz5",
        "zz5",
        "m6",
        "mx6",
        "my6",
        "mz6",
        "xx6",
        "xy6",
        "yy6",
        "xz6",
        "yz6",
        "zz6",
    ];
    const BASE_PARAMETERS: [&'static ::core::primitive::str; 36] = [
        "mx2 + 2159/5000 m2 + 2159/5000 m3 + 2159/5000 m4 + 2159/5000 m5 + 2159/5000 m6",
        "my2",
        "xx2 - yy2 + 4661281/25000000 m2 + 4661281/25000000 m3 + 4661281/25000000 m4 + 4661281/25000000 m5 + 4661281/25000000 m6",
        "xy2",
        "xz2 + 2159/5000 my3 - 2159/5000 mz2 - 6479159/100000000 m3 - 6479159/100000000 m4 - 6479159/100000000 m5 - 6479159/100000000 m6",
        "yz2",
        "zz2 - 4661281/25000000 m2 - 4661281/25000000 m3 - 4661281/25000000 m4 - 4661281/25000000 m5 - 4661281/25000000 m6",
        "mx3 + 203/10000 m3 + 203/10000 m4 + 203/10000 m5 + 203/10000 m6",
        "xx3 - 3001/10000 my3 + yy1 + yy2 - 4661281/25000000 m2 - yy3 - 65409659/400000000 m3 - 65409659/400000000 m4 - 65409659/400000000 m5 - 65409659/400000000 m6",
        "xy3 - 203/10000 my3",
        "xz3",
        "yz3",
        "zz3 - 3001/10000 my3 + yy1 + yy2 - 4661281/25000000 m2 - 65739331/400000000 m3 - 65739331/400000000 m4 - 65739331/400000000 m5 - 65739331/400000000 m6",
        "mx4",
        "my4 + mz3 + 2159/5000 m4 + 2159/5000 m5 + 2159/5000 m6",
        "xx4 + yy3 - 2159/2500 mz3 - 41209/100000000 m3 - yy4 - 18686333/100000000 m4 - 18686333/100000000 m5 - 18686333/100000000 m6",
        "xy4",
        "xz4",
        "yz4",
        "zz4 + yy3 - 2159/2500 mz3 - 41209/100000000 m3 - 18686333/100000000 m4 - 18686333/100000000 m5 - 18686333/100000000 m6",
        "mx5",
        "my5 - mz4",
        "mz5 + mz6",
        "xx5 + yy4 + yy6",
        "xy5",
        "yy5 + yy6",
        "xz5",
        "yz5",
        "zz5 + yy4",
        "mx6",
        "my6",
        "xx6 - yy6",
        "xy6",
        "xz6",
        "yz6",
        "zz6",
    ];
    /**The regressor Y(q, qd, qdd): `Y * standard_parameters() == inverse_dynamics(q, qd, qdd)`. The standard parameters, in column order: per link, in Pinocchio's order, the mass `m` (kg), the first moments `mx`, `my`, `mz` (m c in the link's frame, kg m) and the inertia about the link frame's origin in its axes `xx`, `xy`, `yy`, `xz`, `yz`, `zz` (kg m^2); per joint that has them armature `ia`, damping `fv` and Coulomb friction `fc`; then the payload's ten in the tool frame (`mp`, ..., `zzp`):

1. `m1`
2. `mx1`
3. `my1`
4. `mz1`
5. `xx1`
6. `xy1`
7. `yy1`
8. `xz1`
9. `yz1`
10. `zz1`
11. `m2`
12. `mx2`
13. `my2`
14. `mz2`
15. `xx2`
16. `xy2`
17. `yy2`
18. `xz2`
19. `yz2`
20. `zz2`
21. `m3`
22. `mx3`
23. `my3`
24. `mz3`
25. `xx3`
26. `xy3`
27. `yy3`
28. `xz3`
29. `yz3`
30. `zz3`
31. `m4`
32. `mx4`
33. `my4`
34. `mz4`
35. `xx4`
36. `xy4`
37. `yy4`
38. `xz4`
39. `yz4`
40. `zz4`
41. `m5`
42. `mx5`
43. `my5`
44. `mz5`
45. `xx5`
46. `xy5`
47. `yy5`
48. `xz5`
49. `yz5`
50. `zz5`
51. `m6`
52. `mx6`
53. `my6`
54. `mz6`
55. `xx6`
56. `xy6`
57. `yy6`
58. `xz6`
59. `yz6`
60. `zz6`


the recursive Newton-Euler algorithm unrolled, each link in its own frame, the joints' constant transformations folded in: once per standard parameter, that parameter one and the others zero (the forces are linear in them), the motion of the links shared

Cost: 573 multiplications, 496 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn regressor(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 60> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [__qdd1, __qdd2, __qdd3, __qdd4, __qdd5, __qdd6] = ::planar_arm::__private::unpack(
            __qdd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s3;
        let __t2 = -__s4;
        let __t3 = -__s5;
        let __t4 = -__s6;
        let __t5 = __s2 * __qd1;
        let __t6 = __c2 * __qd1;
        let __t7 = __qd2 * __t6;
        let __t8 = __qd2 * __t5;
        let __t9 = __s2 * __qdd1 + __t7;
        let __t10 = __c2 * __qdd1 - __t8;
        let __t11 = (2159.0 / 5000.0) * __qd2;
        let __t12 = -((2159.0 / 5000.0) * __t6);
        let __t13 = __t5 * __t11 - (2159.0 / 5000.0) * __t10;
        let __t14 = (981.0 / 100.0) * __s2 + __t6 * __t12 - __qd2 * __t11;
        let __t15 = (981.0 / 100.0) * __c2 + (2159.0 / 5000.0) * __qdd2 - __t5 * __t12;
        let __t16 = __c3 * __t5 + __s3 * __t6;
        let __t17 = __t1 * __t5 + __c3 * __t6;
        let __t18 = -__qd2;
        let __t19 = -__qd3;
        let __t20 = __t18 - __qd3;
        let __t21 = -__qdd2 - __qdd3;
        let __t22 = __c3 * __t9 + __s3 * __t10 - __t17 * __t19;
        let __t23 = __t1 * __t9 + __c3 * __t10 + __t16 * __t19;
        let __t24 = -((-(3001.0 / 20000.0)) * __t17);
        let __t25 = (203.0 / 10000.0) * __t17;
        let __t26 = (-(3001.0 / 20000.0)) * __t16 - (203.0 / 10000.0) * __t20;
        let __t27 = __c3 * __t14 + __s3 * __t15 + __t20 * __t26 - __t17 * __t25
            - (-(3001.0 / 20000.0)) * __t23;
        let __t28 = __t17 * __t24 - __t16 * __t26 + (203.0 / 10000.0) * __t23 - __t13;
        let __t29 = __t1 * __t14 + __c3 * __t15 + __t16 * __t25 - __t20 * __t24
            + (-(3001.0 / 20000.0)) * __t22 - (203.0 / 10000.0) * __t21;
        let __t30 = __c4 * __t16 + __s4 * __t20;
        let __t31 = __t2 * __t16 + __c4 * __t20;
        let __t32 = -__t31;
        let __t33 = __t17 + __qd4;
        let __y4_37 = __t23 + __qdd4;
        let __t34 = __c4 * __t22 + __s4 * __t21 - __qd4 * __t32;
        let __t35 = __qd4 * __t30 - (__t2 * __t22 + __c4 * __t21);
        let __t36 = -((2159.0 / 5000.0) * __t32);
        let __t37 = (2159.0 / 5000.0) * __t30;
        let __y4_34 = __c4 * __t27 + __s4 * __t28 + __t33 * __t37
            - (2159.0 / 5000.0) * __t35;
        let __t38 = __t29 + __t32 * __t36 - __t30 * __t37;
        let __t39 = (2159.0 / 5000.0) * __t34 - __t33 * __t36
            - (__t2 * __t27 + __c4 * __t28);
        let __t40 = __c5 * __y4_34 + __s5 * __t38;
        let __y5_42 = __t3 * __y4_34 + __c5 * __t38;
        let __y4_32 = -__t39;
        let __t41 = __c5 * __t30 + __s5 * __t33;
        let __t42 = __t3 * __t30 + __c5 * __t33;
        let __t43 = -__qd5;
        let __t44 = __t31 - __qd5;
        let __t45 = -__t35 - __qdd5;
        let __t46 = __c5 * __t34 + __s5 * __y4_37 - __t42 * __t43;
        let __t47 = __t3 * __t34 + __c5 * __y4_37 + __t41 * __t43;
        let __t48 = __c6 * __t40 + __s6 * __y4_32;
        let __y6_52 = __t4 * __t40 + __c6 * __y4_32;
        let __t49 = __c6 * __t41 + __s6 * __t44;
        let __t50 = __t4 * __t41 + __c6 * __t44;
        let __t51 = __t42 + __qd6;
        let __y6_60 = __t47 + __qdd6;
        let __t52 = __c6 * __t46 + __s6 * __t45 + __qd6 * __t50;
        let __t53 = __t4 * __t46 + __c6 * __t45 - __qd6 * __t49;
        let __t54 = (2159.0 / 5000.0) * __c2;
        let __t55 = -__t54;
        let __t56 = __s2 * __c3 + __c2 * __s3;
        let __t57 = __s2 * __t1 + __c2 * __c3;
        let __t58 = -((-(3001.0 / 20000.0)) * __t57);
        let __t59 = (-(3001.0 / 20000.0)) * __t56;
        let __t60 = __t54 + (203.0 / 10000.0) * __t57;
        let __t61 = (2159.0 / 5000.0) * __s3;
        let __t62 = (203.0 / 10000.0) + (2159.0 / 5000.0) * __c3;
        let __t63 = __c4 * __t56;
        let __t64 = __t2 * __t56;
        let __t65 = -__t64;
        let __t66 = __c4 * __t58 + __s4 * __t60 - (2159.0 / 5000.0) * __t65;
        let __t67 = (2159.0 / 5000.0) * __t63 - (__t2 * __t58 + __c4 * __t60);
        let __t68 = -__c4;
        let __t69 = (2159.0 / 5000.0) * __c4;
        let __t70 = -__t69;
        let __t71 = (2159.0 / 5000.0) * __t2;
        let __t72 = __c4 * __t61 - __t69;
        let __t73 = __t71 - __t2 * __t61;
        let __t74 = __c5 * __t63 + __s5 * __t57;
        let __t75 = __t3 * __t63 + __c5 * __t57;
        let __t76 = __c5 * __t66 + __s5 * __t59;
        let __t77 = __t3 * __t66 + __c5 * __t59;
        let __t78 = -__t67;
        let __t79 = __t2 * __c5;
        let __t80 = __t2 * __t3;
        let __t81 = __c5 * __t72 + __s5 * __t62;
        let __t82 = __t3 * __t72 + __c5 * __t62;
        let __t83 = -__t73;
        let __t84 = __c5 * __t70 + (203.0 / 10000.0) * __s5;
        let __t85 = __t3 * __t70 + (203.0 / 10000.0) * __c5;
        let __t86 = -__t71;
        let __t87 = __c6 * __t74 + __s6 * __t64;
        let __t88 = __t4 * __t74 + __c6 * __t64;
        let __t89 = __c6 * __t76 + __s6 * __t78;
        let __t90 = __t4 * __t76 + __c6 * __t78;
        let __t91 = __c6 * __t79 + __s6 * __t68;
        let __t92 = __t4 * __t79 + __c6 * __t68;
        let __t93 = __c6 * __t81 + __s6 * __t83;
        let __t94 = __t4 * __t81 + __c6 * __t83;
        let __t95 = __c6 * __t84 + __s6 * __t86;
        let __t96 = __t4 * __t84 + __c6 * __t86;
        let __t97 = __s5 * __c6;
        let __t98 = __s5 * __t4;
        let __t99 = -__c6;
        let __y1_11 = __t13 * __t55;
        let __y2_11 = (2159.0 / 5000.0) * __t15;
        let __t100 = __qd2 * __qd2;
        let __y1_12 = __t55 * (__t8 - __t10) + __c2 * (-__t13);
        let __y2_12 = __t15 + (2159.0 / 5000.0) * (__qdd2 - __t5 * (-__t6));
        let __y2_17 = __t5 * __t6;
        let __t101 = __t5 * __t5;
        let __y1_13 = __t55 * (__t9 - __t6 * __t18) + __s2 * __t13;
        let __y2_13 = (2159.0 / 5000.0) * (__qd2 * __t18 - __t101) - __t14;
        let __t102 = __t6 * __t6;
        let __y1_14 = __t55 * (__t5 * (-__t5) - __t102) + __s2 * (-__t15) + __c2 * __t14;
        let __y2_14 = (2159.0 / 5000.0) * (__t7 - __t9);
        let __y2_15 = -__y2_17;
        let __y1_15 = __s2 * __t9 + __c2 * __t8;
        let __y2_16 = __t101 - __t102;
        let __y1_16 = __s2 * (__t10 - __t8) + __c2 * (__t7 + __t9);
        let __y1_17 = __s2 * (-__t7) + __c2 * __t10;
        let __y2_18 = __t9 - __t7;
        let __y1_18 = __s2 * (__qdd2 + __y2_17) + __c2 * (__t100 - __t101);
        let __y2_19 = __t8 + __t10;
        let __y1_19 = __s2 * (__t102 - __t100) + __c2 * (__qdd2 - __y2_17);
        let __y1_20 = __s2 * __t7 + __c2 * (-__t8);
        let __y1_21 = __t29 * __t59 + __t27 * __t58 + __t28 * __t60;
        let __y2_21 = __t27 * __t61 + __t29 * __t62;
        let __y3_21 = (203.0 / 10000.0) * __t29;
        let __y2_27 = -__t21;
        let __t103 = -__t20;
        let __t104 = __t17 * __t17;
        let __t105 = __t20 * __t103 - __t104;
        let __y2_30 = __t16 * __t17;
        let __t106 = __y2_30 - __t21;
        let __y1_22 = __t59 * __t106 + __t58 * __t105 + __t60 * (__t23 - __t16 * __t103)
            + __t28 * __t57;
        let __y2_22 = __t29 + __t61 * __t105 + __t62 * __t106;
        let __y3_22 = __t29 + (203.0 / 10000.0) * __t106;
        let __t107 = -__t17;
        let __t108 = __t16 * __t20;
        let __t109 = __t16 * __t16;
        let __t110 = __t108 - __t23;
        let __t111 = __t22 - __t20 * __t107;
        let __y1_23 = __t59 * __t111 + __t58 * __t110 + __t60 * (__t17 * __t107 - __t109)
            + __t29 * __t56 + __t57 * (-__t27);
        let __y2_23 = __t61 * __t110 + __t62 * __t111;
        let __y3_23 = (203.0 / 10000.0) * __t111;
        let __t112 = -__t16;
        let __t113 = __t17 * __t20;
        let __t114 = __t20 * __t20;
        let __t115 = __t16 * __t112 - __t114;
        let __t116 = __t21 - __t17 * __t112;
        let __y1_24 = __t59 * __t115 + __t58 * __t116 + __t60 * (__t113 - __t22)
            + __t56 * (-__t28);
        let __y2_24 = __t61 * __t116 + __t62 * __t115 - __t27;
        let __y3_24 = (203.0 / 10000.0) * __t115 - __t27;
        let __y1_25 = __t22 * __t56 + __t57 * (-__t108);
        let __y2_25 = -__y2_30;
        let __y1_26 = __t56 * (__t21 - __y2_30) + __t57 * (__t109 - __t114);
        let __y2_26 = -(__t22 + __t113);
        let __y1_27 = __t56 * (-__t113) + __t57 * __t108;
        let __y1_28 = __t56 * (__t23 + __t108) + __t57 * (__t22 - __t113);
        let __y2_28 = -(__t104 - __t109);
        let __y1_29 = __t56 * (__t114 - __t104) + __t57 * (__t21 + __y2_30);
        let __y2_29 = -(__t23 - __t108);
        let __y1_30 = __t56 * __t113 + __t23 * __t57;
        let __y1_31 = __t39 * __t67 + __y4_34 * __t66 + __t38 * __t59;
        let __y2_31 = __t39 * __t73 + __y4_34 * __t72 + __t38 * __t62;
        let __y3_31 = __t39 * __t71 + __y4_34 * __t70 + (203.0 / 10000.0) * __t38;
        let __t117 = -__t33;
        let __t118 = __t32 * __t32;
        let __t119 = __t33 * __t117 - __t118;
        let __y4_35 = __t30 * __t32;
        let __t120 = __t35 - __t30 * __t117;
        let __t121 = __y4_35 - __y4_37;
        let __y1_32 = __t67 * __t121 + __t66 * __t119 + __t59 * __t120 + __y4_32 * __t57
            + __t38 * __t65;
        let __t122 = __c4 * __t38;
        let __y2_32 = __t73 * __t121 + __t72 * __t119 + __t62 * __t120 + __t122;
        let __y3_32 = __t122 + __t71 * __t121 + __t70 * __t119
            + (203.0 / 10000.0) * __t120;
        let __t123 = __t30 * __t33;
        let __t124 = __t30 * __t30;
        let __t125 = __t31 * __t32 - __t124;
        let __t126 = __t123 - __t35;
        let __t127 = __t34 - __t31 * __t33;
        let __t128 = -__y4_34;
        let __y1_33 = __t67 * __t127 + __t66 * __t126 + __t59 * __t125 + __t39 * __t63
            + __t65 * __t128;
        let __t129 = __t2 * __t39 + __c4 * __t128;
        let __y2_33 = __t73 * __t127 + __t72 * __t126 + __t62 * __t125 + __t129;
        let __y3_33 = __t129 + __t71 * __t127 + __t70 * __t126
            + (203.0 / 10000.0) * __t125;
        let __t130 = -__t30;
        let __t131 = __t32 * __t33;
        let __t132 = __t33 * __t33;
        let __t133 = __t30 * __t130 - __t132;
        let __t134 = __y4_37 - __t32 * __t130;
        let __t135 = __t131 - __t34;
        let __t136 = -__t38;
        let __y1_34 = __t67 * __t133 + __t66 * __t134 + __t59 * __t135 + __t63 * __t136
            + __y4_34 * __t57;
        let __t137 = __t2 * __t136;
        let __y2_34 = __t73 * __t133 + __t72 * __t134 + __t62 * __t135 + __t137;
        let __y3_34 = __t137 + __t71 * __t133 + __t70 * __t134
            + (203.0 / 10000.0) * __t135;
        let __t138 = -__t123;
        let __y1_35 = __t65 * __t138 + __t34 * __t63 + __t57 * __y4_35;
        let __y2_35 = __t2 * __t34 + __c4 * __t138;
        let __y4_40 = -__y4_35;
        let __t139 = __t124 - __t132;
        let __t140 = __y4_37 - __y4_35;
        let __y4_36 = __t34 + __t131;
        let __y1_36 = __t65 * __t139 + __t63 * __t140 + __t57 * __y4_36;
        let __y2_36 = __t2 * __t140 + __c4 * __t139;
        let __t141 = -__t131;
        let __y1_37 = __t65 * __t123 + __t63 * __t141 + __y4_37 * __t57;
        let __y2_37 = __t2 * __t141 + __c4 * __t123;
        let __y4_38 = __t118 - __t124;
        let __t142 = __t35 + __t123;
        let __t143 = __t34 - __t131;
        let __y1_38 = __t65 * __t143 + __t63 * __t142 + __t57 * __y4_38;
        let __y2_38 = __t2 * __t142 + __c4 * __t143;
        let __t144 = __t132 - __t118;
        let __y4_39 = __t35 - __t123;
        let __t145 = __y4_37 + __y4_35;
        let __y1_39 = __t65 * __t145 + __t63 * __t144 + __t57 * __y4_39;
        let __y2_39 = __t2 * __t144 + __c4 * __t145;
        let __y1_40 = __t35 * __t65 + __t63 * __t131 + __t57 * __y4_40;
        let __y2_40 = __t2 * __t131 + __c4 * __t35;
        let __t146 = __y5_42 * __t77;
        let __y1_41 = __t146 + __t40 * __t76 + __y4_32 * __t78;
        let __t147 = __y5_42 * __t82;
        let __y2_41 = __t147 + __t40 * __t81 + __y4_32 * __t83;
        let __t148 = __y5_42 * __t85;
        let __y3_41 = __t148 + __t40 * __t84 + __y4_32 * __t86;
        let __y5_47 = -__t45;
        let __t149 = -__t44;
        let __t150 = __t42 * __t42;
        let __t151 = __t44 * __t149 - __t150;
        let __y5_50 = __t41 * __t42;
        let __t152 = __t47 - __t41 * __t149;
        let __t153 = __y5_50 - __t45;
        let __t154 = -__y5_42;
        let __y1_42 = __t77 * __t153 + __t76 * __t151 + __t78 * __t152 + __t64 * __t154
            + __y4_32 * __t75;
        let __t155 = __t68 * __t154 + __y4_32 * __t80;
        let __y2_42 = __t82 * __t153 + __t81 * __t151 + __t83 * __t152 + __t155;
        let __y3_42 = __t155 + __t85 * __t153 + __t84 * __t151 + __t86 * __t152;
        let __y4_42 = __c5 * __y4_32;
        let __t156 = -__t42;
        let __t157 = __t41 * __t44;
        let __t158 = __t41 * __t41;
        let __t159 = __t42 * __t156 - __t158;
        let __t160 = __t157 - __t47;
        let __t161 = __t46 - __t44 * __t156;
        let __y5_44 = -__t40;
        let __y1_43 = __t77 * __t161 + __t76 * __t160 + __t78 * __t159 + __y5_42 * __t74
            + __t75 * __y5_44;
        let __t162 = __y5_42 * __t79 + __t80 * __y5_44;
        let __y2_43 = __t82 * __t161 + __t81 * __t160 + __t83 * __t159 + __t162;
        let __y3_43 = __t162 + __t85 * __t161 + __t84 * __t160 + __t86 * __t159;
        let __y4_43 = __s5 * __y5_42 + __c5 * __y5_44;
        let __t163 = -__t41;
        let __t164 = __t42 * __t44;
        let __t165 = __t44 * __t44;
        let __t166 = __t41 * __t163 - __t165;
        let __t167 = __t45 - __t42 * __t163;
        let __t168 = __t164 - __t46;
        let __y1_44 = __t77 * __t166 + __t76 * __t167 + __t78 * __t168 + __t39 * __t74
            + __t40 * __t64;
        let __t169 = __t39 * __t79 + __t40 * __t68;
        let __y2_44 = __t82 * __t166 + __t81 * __t167 + __t83 * __t168 + __t169;
        let __y3_44 = __t169 + __t85 * __t166 + __t84 * __t167 + __t86 * __t168;
        let __y4_44 = __s5 * __t39;
        let __t170 = -__t157;
        let __y1_45 = __t75 * __t170 + __t46 * __t74 + __t64 * __y5_50;
        let __y2_45 = __t80 * __t170 + __t46 * __t79 + __t68 * __y5_50;
        let __y4_45 = __s5 * __t46 + __c5 * __t170;
        let __y5_45 = -__y5_50;
        let __t171 = __t158 - __t165;
        let __t172 = __t45 - __y5_50;
        let __t173 = __t46 + __t164;
        let __y1_46 = __t75 * __t171 + __t74 * __t172 + __t64 * __t173;
        let __y2_46 = __t80 * __t171 + __t79 * __t172 + __t68 * __t173;
        let __y4_46 = __s5 * __t172 + __c5 * __t171;
        let __y5_46 = -__t173;
        let __t174 = -__t164;
        let __y1_47 = __t75 * __t157 + __t74 * __t174 + __t45 * __t64;
        let __y2_47 = __t80 * __t157 + __t79 * __t174 + __t45 * __t68;
        let __y4_47 = __s5 * __t174 + __c5 * __t157;
        let __t175 = __t150 - __t158;
        let __t176 = __t47 + __t157;
        let __t177 = __t46 - __t164;
        let __y1_48 = __t75 * __t177 + __t74 * __t176 + __t64 * __t175;
        let __y2_48 = __t80 * __t177 + __t79 * __t176 + __t68 * __t175;
        let __y4_48 = __s5 * __t176 + __c5 * __t177;
        let __y5_48 = -__t175;
        let __t178 = __t165 - __t150;
        let __t179 = __t47 - __t157;
        let __t180 = __t45 + __y5_50;
        let __y1_49 = __t75 * __t180 + __t74 * __t178 + __t64 * __t179;
        let __y2_49 = __t80 * __t180 + __t79 * __t178 + __t68 * __t179;
        let __y4_49 = __s5 * __t178 + __c5 * __t180;
        let __y5_49 = -__t179;
        let __y1_50 = __t47 * __t75 + __t74 * __t164 + __t64 * __y5_45;
        let __y2_50 = __t47 * __t80 + __t79 * __t164 + __t68 * __y5_45;
        let __y4_50 = __s5 * __t164 + __c5 * __t47;
        let __y1_51 = __t146 + __t48 * __t89 + __y6_52 * __t90;
        let __y2_51 = __t147 + __t48 * __t93 + __y6_52 * __t94;
        let __y3_51 = __t148 + __t48 * __t95 + __y6_52 * __t96;
        let __t181 = -__t50;
        let __t182 = __t51 * __t51;
        let __t183 = __t50 * __t181 - __t182;
        let __t184 = __t49 * __t51;
        let __t185 = __y6_60 - __t49 * __t181;
        let __t186 = __t184 - __t53;
        let __y1_52 = __t77 * __t186 + __t89 * __t183 + __t90 * __t185 + __t88 * __t154
            + __y6_52 * __t75;
        let __t187 = __t92 * __t154 + __y6_52 * __t80;
        let __y2_52 = __t82 * __t186 + __t93 * __t183 + __t94 * __t185 + __t187;
        let __y3_52 = __t187 + __t85 * __t186 + __t95 * __t183 + __t96 * __t185;
        let __y4_52 = __t98 * __t154 + __c5 * __y6_52;
        let __y5_52 = __t99 * __t154;
        let __t188 = -__t51;
        let __y6_57 = __t49 * __t50;
        let __t189 = __t49 * __t49;
        let __t190 = __t51 * __t188 - __t189;
        let __t191 = __y6_57 - __y6_60;
        let __t192 = __t52 - __t50 * __t188;
        let __y6_53 = -__t48;
        let __y1_53 = __t77 * __t192 + __t89 * __t191 + __t90 * __t190 + __y5_42 * __t87
            + __t75 * __y6_53;
        let __t193 = __y5_42 * __t91 + __t80 * __y6_53;
        let __y2_53 = __t82 * __t192 + __t93 * __t191 + __t94 * __t190 + __t193;
        let __y3_53 = __t193 + __t85 * __t192 + __t95 * __t191 + __t96 * __t190;
        let __y4_53 = __y5_42 * __t97 + __c5 * __y6_53;
        let __y5_53 = __t4 * __y5_42;
        let __t194 = -__t49;
        let __t195 = __t50 * __t51;
        let __t196 = __t50 * __t50;
        let __t197 = __t49 * __t194 - __t196;
        let __t198 = __t53 - __t51 * __t194;
        let __t199 = __t195 - __t52;
        let __t200 = -__y6_52;
        let __y1_54 = __t77 * __t197 + __t89 * __t198 + __t90 * __t199 + __t87 * __t200
            + __t48 * __t88;
        let __t201 = __t91 * __t200 + __t48 * __t92;
        let __y2_54 = __t82 * __t197 + __t93 * __t198 + __t94 * __t199 + __t201;
        let __y3_54 = __t201 + __t85 * __t197 + __t95 * __t198 + __t96 * __t199;
        let __y4_54 = __t97 * __t200 + __t48 * __t98;
        let __y5_54 = __t4 * __t200 + __t48 * __t99;
        let __y6_55 = -__y6_57;
        let __y1_55 = __t75 * __y6_55 + __t52 * __t87 + __t88 * __t184;
        let __y2_55 = __t80 * __y6_55 + __t52 * __t91 + __t92 * __t184;
        let __y4_55 = __c5 * __y6_55 + __t52 * __t97 + __t98 * __t184;
        let __y5_55 = __t4 * __t52 + __t99 * __t184;
        let __t202 = -__t184;
        let __y6_56 = __t189 - __t196;
        let __t203 = __t53 - __t184;
        let __t204 = __t52 + __t195;
        let __y1_56 = __t75 * __y6_56 + __t87 * __t203 + __t88 * __t204;
        let __y2_56 = __t80 * __y6_56 + __t91 * __t203 + __t92 * __t204;
        let __y4_56 = __c5 * __y6_56 + __t97 * __t203 + __t98 * __t204;
        let __y5_56 = __t4 * __t203 + __t99 * __t204;
        let __t205 = -__t195;
        let __y1_57 = __t75 * __y6_57 + __t87 * __t205 + __t53 * __t88;
        let __y2_57 = __t80 * __y6_57 + __t91 * __t205 + __t53 * __t92;
        let __y4_57 = __c5 * __y6_57 + __t97 * __t205 + __t53 * __t98;
        let __y5_57 = __t4 * __t205 + __t53 * __t99;
        let __t206 = __t182 - __t189;
        let __t207 = __y6_60 + __y6_57;
        let __y6_58 = __t52 - __t195;
        let __y1_58 = __t75 * __y6_58 + __t87 * __t207 + __t88 * __t206;
        let __y2_58 = __t80 * __y6_58 + __t91 * __t207 + __t92 * __t206;
        let __y4_58 = __c5 * __y6_58 + __t97 * __t207 + __t98 * __t206;
        let __y5_58 = __t4 * __t207 + __t99 * __t206;
        let __t208 = __t196 - __t182;
        let __t209 = __y6_60 - __y6_57;
        let __y6_59 = __t53 + __t184;
        let __y1_59 = __t75 * __y6_59 + __t87 * __t208 + __t88 * __t209;
        let __y2_59 = __t80 * __y6_59 + __t91 * __t208 + __t92 * __t209;
        let __y4_59 = __c5 * __y6_59 + __t97 * __t208 + __t98 * __t209;
        let __y5_59 = __t4 * __t208 + __t99 * __t209;
        let __y1_60 = __y6_60 * __t75 + __t87 * __t195 + __t88 * __t202;
        let __y2_60 = __y6_60 * __t80 + __t91 * __t195 + __t92 * __t202;
        let __y4_60 = __c5 * __y6_60 + __t97 * __t195 + __t98 * __t202;
        let __y5_60 = __t4 * __t195 + __t99 * __t202;
        let __y1_1 = 0.0;
        ::planar_arm::__private::columns([
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__qdd1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_1, __y1_1, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_11, __y2_11, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_12, __y2_12, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_13, __y2_13, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_14, __y2_14, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_15, __y2_15, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_16, __y2_16, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_17, __y2_17, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_18, __y2_18, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_19, __y2_19, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_20, __qdd2, __y1_1, __y1_1, __y1_1, __y1_1],
            [__y1_21, __y2_21, __y3_21, __y1_1, __y1_1, __y1_1],
            [__y1_22, __y2_22, __y3_22, __y1_1, __y1_1, __y1_1],
            [__y1_23, __y2_23, __y3_23, __y1_1, __y1_1, __y1_1],
            [__y1_24, __y2_24, __y3_24, __y1_1, __y1_1, __y1_1],
            [__y1_25, __y2_25, __y2_25, __y1_1, __y1_1, __y1_1],
            [__y1_26, __y2_26, __y2_26, __y1_1, __y1_1, __y1_1],
            [__y1_27, __y2_27, __y2_27, __y1_1, __y1_1, __y1_1],
            [__y1_28, __y2_28, __y2_28, __y1_1, __y1_1, __y1_1],
            [__y1_29, __y2_29, __y2_29, __y1_1, __y1_1, __y1_1],
            [__y1_30, __y2_30, __y2_30, __y1_1, __y1_1, __y1_1],
            [__y1_31, __y2_31, __y3_31, __y1_1, __y1_1, __y1_1],
            [__y1_32, __y2_32, __y3_32, __y4_32, __y1_1, __y1_1],
            [__y1_33, __y2_33, __y3_33, __y1_1, __y1_1, __y1_1],
            [__y1_34, __y2_34, __y3_34, __y4_34, __y1_1, __y1_1],
            [__y1_35, __y2_35, __y2_35, __y4_35, __y1_1, __y1_1],
            [__y1_36, __y2_36, __y2_36, __y4_36, __y1_1, __y1_1],
            [__y1_37, __y2_37, __y2_37, __y4_37, __y1_1, __y1_1],
            [__y1_38, __y2_38, __y2_38, __y4_38, __y1_1, __y1_1],
            [__y1_39, __y2_39, __y2_39, __y4_39, __y1_1, __y1_1],
            [__y1_40, __y2_40, __y2_40, __y4_40, __y1_1, __y1_1],
            [__y1_41, __y2_41, __y3_41, __y1_1, __y1_1, __y1_1],
            [__y1_42, __y2_42, __y3_42, __y4_42, __y5_42, __y1_1],
            [__y1_43, __y2_43, __y3_43, __y4_43, __y1_1, __y1_1],
            [__y1_44, __y2_44, __y3_44, __y4_44, __y5_44, __y1_1],
            [__y1_45, __y2_45, __y2_45, __y4_45, __y5_45, __y1_1],
            [__y1_46, __y2_46, __y2_46, __y4_46, __y5_46, __y1_1],
            [__y1_47, __y2_47, __y2_47, __y4_47, __y5_47, __y1_1],
            [__y1_48, __y2_48, __y2_48, __y4_48, __y5_48, __y1_1],
            [__y1_49, __y2_49, __y2_49, __y4_49, __y5_49, __y1_1],
            [__y1_50, __y2_50, __y2_50, __y4_50, __y5_50, __y1_1],
            [__y1_51, __y2_51, __y3_51, __y1_1, __y1_1, __y1_1],
            [__y1_52, __y2_52, __y3_52, __y4_52, __y5_52, __y6_52],
            [__y1_53, __y2_53, __y3_53, __y4_53, __y5_53, __y6_53],
            [__y1_54, __y2_54, __y3_54, __y4_54, __y5_54, __y1_1],
            [__y1_55, __y2_55, __y2_55, __y4_55, __y5_55, __y6_55],
            [__y1_56, __y2_56, __y2_56, __y4_56, __y5_56, __y6_56],
            [__y1_57, __y2_57, __y2_57, __y4_57, __y5_57, __y6_57],
            [__y1_58, __y2_58, __y2_58, __y4_58, __y5_58, __y6_58],
            [__y1_59, __y2_59, __y2_59, __y4_59, __y5_59, __y6_59],
            [__y1_60, __y2_60, __y2_60, __y4_60, __y5_60, __y6_60],
        ])
    }
    /**The arm's standard parameters now (run-time parameters read from their fields). The standard parameters, in column order: per link, in Pinocchio's order, the mass `m` (kg), the first moments `mx`, `my`, `mz` (m c in the link's frame, kg m) and the inertia about the link frame's origin in its axes `xx`, `xy`, `yy`, `xz`, `yz`, `zz` (kg m^2); per joint that has them armature `ia`, damping `fv` and Coulomb friction `fc`; then the payload's ten in the tool frame (`mp`, ..., `zzp`):

1. `m1`
2. `mx1`
3. `my1`
4. `mz1`
5. `xx1`
6. `xy1`
7. `yy1`
8. `xz1`
9. `yz1`
10. `zz1`
11. `m2`
12. `mx2`
13. `my2`
14. `mz2`
15. `xx2`
16. `xy2`
17. `yy2`
18. `xz2`
19. `yz2`
20. `zz2`
21. `m3`
22. `mx3`
23. `my3`
24. `mz3`
25. `xx3`
26. `xy3`
27. `yy3`
28. `xz3`
29. `yz3`
30. `zz3`
31. `m4`
32. `mx4`
33. `my4`
34. `mz4`
35. `xx4`
36. `xy4`
37. `yy4`
38. `xz4`
39. `yz4`
40. `zz4`
41. `m5`
42. `mx5`
43. `my5`
44. `mz5`
45. `xx5`
46. `xy5`
47. `yy5`
48. `xz5`
49. `yz5`
50. `zz5`
51. `m6`
52. `mx6`
53. `my6`
54. `mz6`
55. `xx6`
56. `xy6`
57. `yy6`
58. `xz6`
59. `yz6`
60. `zz6`


Cost: 0 multiplications, 0 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn standard_parameters(
        &self,
    ) -> ::planar_arm::nalgebra::SVector<::core::primitive::f64, 60> {
        let __m1 = 0.0;
        let __m2 = (87.0 / 5.0);
        let __mx2 = (-(158253.0 / 25000.0));
        let __my2 = (261.0 / 2500.0);
        let __mz2 = (7917.0 / 2000.0);
        let __xx2 = (18023703.0 / 20000000.0);
        let __xy2 = (474759.0 / 12500000.0);
        let __yy2 = (1601728203.0 / 500000000.0);
        let __xz2 = (14401023.0 / 10000000.0);
        let __yz2 = (-(23751.0 / 1000000.0));
        let __zz2 = (287940507.0 / 125000000.0);
        let __m3 = (24.0 / 5.0);
        let __mx3 = (-(609.0 / 6250.0));
        let __my3 = (-(423.0 / 6250.0));
        let __mz3 = (42.0 / 125.0);
        let __xx3 = (1529643.0 / 62500000.0);
        let __xy3 = (-(85869.0 / 62500000.0));
        let __yy3 = (1593627.0 / 62500000.0);
        let __xz3 = (4263.0 / 625000.0);
        let __yz3 = (2961.0 / 625000.0);
        let __zz3 = (18327.0 / 6250000.0);
        let __m4 = (41.0 / 50.0);
        let __my4 = (779.0 / 50000.0);
        let __xx4 = (14801.0 / 50000000.0);
        let __m5 = (17.0 / 50.0);
        let __m6 = (9.0 / 100.0);
        let __mz6 = (9.0 / 3125.0);
        let __xx6 = (36.0 / 390625.0);
        ::planar_arm::__private::vector([
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m2,
            __mx2,
            __my2,
            __mz2,
            __xx2,
            __xy2,
            __yy2,
            __xz2,
            __yz2,
            __zz2,
            __m3,
            __mx3,
            __my3,
            __mz3,
            __xx3,
            __xy3,
            __yy3,
            __xz3,
            __yz3,
            __zz3,
            __m4,
            __m1,
            __my4,
            __m1,
            __xx4,
            __m1,
            __m1,
            __m1,
            __m1,
            __xx4,
            __m5,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m1,
            __m6,
            __m1,
            __m1,
            __mz6,
            __xx6,
            __m1,
            __xx6,
            __m1,
            __m1,
            __m1,
        ])
    }
    /**The base regressor: the regressor's columns of the base parameters, `Y_b * base_parameters() == inverse_dynamics(q, qd, qdd)`. The base parameters, each an exact combination of the standard ones, found at compile time by rational elimination on the regressor evaluated exactly at rational points:

1. `mx2 + 2159/5000 m2 + 2159/5000 m3 + 2159/5000 m4 + 2159/5000 m5 + 2159/5000 m6`
2. `my2`
3. `xx2 - yy2 + 4661281/25000000 m2 + 4661281/25000000 m3 + 4661281/25000000 m4 + 4661281/25000000 m5 + 4661281/25000000 m6`
4. `xy2`
5. `xz2 + 2159/5000 my3 - 2159/5000 mz2 - 6479159/100000000 m3 - 6479159/100000000 m4 - 6479159/100000000 m5 - 6479159/100000000 m6`
6. `yz2`
7. `zz2 - 4661281/25000000 m2 - 4661281/25000000 m3 - 4661281/25000000 m4 - 4661281/25000000 m5 - 4661281/25000000 m6`
8. `mx3 + 203/10000 m3 + 203/10000 m4 + 203/10000 m5 + 203/10000 m6`
9. `xx3 - 3001/10000 my3 + yy1 + yy2 - 4661281/25000000 m2 - yy3 - 65409659/400000000 m3 - 65409659/400000000 m4 - 65409659/400000000 m5 - 65409659/400000000 m6`
10. `xy3 - 203/10000 my3`
11. `xz3`
12. `yz3`
13. `zz3 - 3001/10000 my3 + yy1 + yy2 - 4661281/25000000 m2 - 65739331/400000000 m3 - 65739331/400000000 m4 - 65739331/400000000 m5 - 65739331/400000000 m6`
14. `mx4`
15. `my4 + mz3 + 2159/5000 m4 + 2159/5000 m5 + 2159/5000 m6`
16. `xx4 + yy3 - 2159/2500 mz3 - 41209/100000000 m3 - yy4 - 18686333/100000000 m4 - 18686333/100000000 m5 - 18686333/100000000 m6`
17. `xy4`
18. `xz4`
19. `yz4`
20. `zz4 + yy3 - 2159/2500 mz3 - 41209/100000000 m3 - 18686333/100000000 m4 - 18686333/100000000 m5 - 18686333/100000000 m6`
21. `mx5`
22. `my5 - mz4`
23. `mz5 + mz6`
24. `xx5 + yy4 + yy6`
25. `xy5`
26. `yy5 + yy6`
27. `xz5`
28. `yz5`
29. `zz5 + yy4`
30. `mx6`
31. `my6`
32. `xx6 - yy6`
33. `xy6`
34. `xz6`
35. `yz6`
36. `zz6`


the recursive Newton-Euler algorithm unrolled, each link in its own frame, the joints' constant transformations folded in: once per standard parameter, that parameter one and the others zero (the forces are linear in them), the motion of the links shared

Cost: 464 multiplications, 398 additions, 0 divisions, 5 sin_cos pairs; where the processor has AVX2 and FMA, 141 multiplications, 177 additions, 0 divisions, 5 sin_cos pairs on scalars and 212 four-lane operations (112 of them fused multiply-adds).*/
    #[inline]
    fn base_regressor(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 36> {
        ::planar_arm::__private::dispatch(::planar_arm::__private::BaseRegressor::<
            Self,
            6,
            60,
            36,
        > {
            arm: self,
            q: __q,
            qd: __qd,
            qdd: __qdd,
        })
    }
    #[doc(hidden)]
    #[inline(always)]
    fn __base_regressor_kernel(
        &self,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 36> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [__qdd1, __qdd2, __qdd3, __qdd4, __qdd5, __qdd6] = ::planar_arm::__private::unpack(
            __qdd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __t1 = -__s3;
        let __t2 = -__s4;
        let __t3 = -__s5;
        let __t4 = -__s6;
        let __t5 = __s2 * __qd1;
        let __t6 = __c2 * __qd1;
        let __t7 = __qd2 * __t6;
        let __t8 = __qd2 * __t5;
        let __t9 = __s2 * __qdd1 + __t7;
        let __t10 = __c2 * __qdd1 - __t8;
        let __t11 = (2159.0 / 5000.0) * __qd2;
        let __t12 = -((2159.0 / 5000.0) * __t6);
        let __t13 = __t5 * __t11 - (2159.0 / 5000.0) * __t10;
        let __t14 = (981.0 / 100.0) * __s2 + __t6 * __t12 - __qd2 * __t11;
        let __t15 = (981.0 / 100.0) * __c2 + (2159.0 / 5000.0) * __qdd2 - __t5 * __t12;
        let __t16 = __c3 * __t5 + __s3 * __t6;
        let __t17 = __t1 * __t5 + __c3 * __t6;
        let __t18 = -__qd2;
        let __t19 = -__qd3;
        let __t20 = __t18 - __qd3;
        let __t21 = -__qdd2 - __qdd3;
        let __t22 = __c3 * __t9 + __s3 * __t10 - __t17 * __t19;
        let __t23 = __t1 * __t9 + __c3 * __t10 + __t16 * __t19;
        let __t24 = -((-(3001.0 / 20000.0)) * __t17);
        let __t25 = (203.0 / 10000.0) * __t17;
        let __t26 = (-(3001.0 / 20000.0)) * __t16 - (203.0 / 10000.0) * __t20;
        let __t27 = __c3 * __t14 + __s3 * __t15 + __t20 * __t26 - __t17 * __t25
            - (-(3001.0 / 20000.0)) * __t23;
        let __t28 = __t17 * __t24 - __t16 * __t26 + (203.0 / 10000.0) * __t23 - __t13;
        let __t29 = __t1 * __t14 + __c3 * __t15 + __t16 * __t25 - __t20 * __t24
            + (-(3001.0 / 20000.0)) * __t22 - (203.0 / 10000.0) * __t21;
        let __t30 = __c4 * __t16 + __s4 * __t20;
        let __t31 = __t2 * __t16 + __c4 * __t20;
        let __t32 = -__t31;
        let __t33 = __t17 + __qd4;
        let __t34 = __t23 + __qdd4;
        let __t35 = __c4 * __t22 + __s4 * __t21 - __qd4 * __t32;
        let __t36 = __qd4 * __t30 - (__t2 * __t22 + __c4 * __t21);
        let __t37 = -((2159.0 / 5000.0) * __t32);
        let __t38 = (2159.0 / 5000.0) * __t30;
        let __t39 = __c4 * __t27 + __s4 * __t28 + __t33 * __t38
            - (2159.0 / 5000.0) * __t36;
        let __t40 = __t29 + __t32 * __t37 - __t30 * __t38;
        let __t41 = (2159.0 / 5000.0) * __t35 - __t33 * __t37
            - (__t2 * __t27 + __c4 * __t28);
        let __t42 = __c5 * __t39 + __s5 * __t40;
        let __y5_21 = __t3 * __t39 + __c5 * __t40;
        let __y4_14 = -__t41;
        let __t43 = __c5 * __t30 + __s5 * __t33;
        let __t44 = __t3 * __t30 + __c5 * __t33;
        let __t45 = -__qd5;
        let __t46 = __t31 - __qd5;
        let __t47 = -__t36 - __qdd5;
        let __t48 = __c5 * __t35 + __s5 * __t34 - __t44 * __t45;
        let __t49 = __t3 * __t35 + __c5 * __t34 + __t43 * __t45;
        let __y6_30 = __t4 * __t42 + __c6 * __y4_14;
        let __t50 = __c6 * __t43 + __s6 * __t46;
        let __t51 = __t4 * __t43 + __c6 * __t46;
        let __t52 = __t44 + __qd6;
        let __y6_36 = __t49 + __qdd6;
        let __t53 = __c6 * __t48 + __s6 * __t47 + __qd6 * __t51;
        let __t54 = __t4 * __t48 + __c6 * __t47 - __qd6 * __t50;
        let __t55 = (2159.0 / 5000.0) * __c2;
        let __t56 = -__t55;
        let __t57 = __s2 * __c3 + __c2 * __s3;
        let __t58 = __s2 * __t1 + __c2 * __c3;
        let __t59 = -((-(3001.0 / 20000.0)) * __t58);
        let __t60 = (-(3001.0 / 20000.0)) * __t57;
        let __t61 = __t55 + (203.0 / 10000.0) * __t58;
        let __t62 = (2159.0 / 5000.0) * __s3;
        let __t63 = (203.0 / 10000.0) + (2159.0 / 5000.0) * __c3;
        let __t64 = __c4 * __t57;
        let __t65 = __t2 * __t57;
        let __t66 = -__t65;
        let __t67 = __c4 * __t59 + __s4 * __t61 - (2159.0 / 5000.0) * __t66;
        let __t68 = (2159.0 / 5000.0) * __t64 - (__t2 * __t59 + __c4 * __t61);
        let __t69 = -__c4;
        let __t70 = (2159.0 / 5000.0) * __c4;
        let __t71 = -__t70;
        let __t72 = (2159.0 / 5000.0) * __t2;
        let __t73 = __c4 * __t62 - __t70;
        let __t74 = __t72 - __t2 * __t62;
        let __t75 = __c5 * __t64 + __s5 * __t58;
        let __t76 = __t3 * __t64 + __c5 * __t58;
        let __t77 = __c5 * __t67 + __s5 * __t60;
        let __t78 = __t3 * __t67 + __c5 * __t60;
        let __t79 = -__t68;
        let __t80 = __t2 * __c5;
        let __t81 = __t2 * __t3;
        let __t82 = __c5 * __t73 + __s5 * __t63;
        let __t83 = __t3 * __t73 + __c5 * __t63;
        let __t84 = -__t74;
        let __t85 = __c5 * __t71 + (203.0 / 10000.0) * __s5;
        let __t86 = __t3 * __t71 + (203.0 / 10000.0) * __c5;
        let __t87 = -__t72;
        let __t88 = __c6 * __t75 + __s6 * __t65;
        let __t89 = __t4 * __t75 + __c6 * __t65;
        let __t90 = __c6 * __t77 + __s6 * __t79;
        let __t91 = __t4 * __t77 + __c6 * __t79;
        let __t92 = __c6 * __t80 + __s6 * __t69;
        let __t93 = __t4 * __t80 + __c6 * __t69;
        let __t94 = __c6 * __t82 + __s6 * __t84;
        let __t95 = __t4 * __t82 + __c6 * __t84;
        let __t96 = __c6 * __t85 + __s6 * __t87;
        let __t97 = __t4 * __t85 + __c6 * __t87;
        let __t98 = __s5 * __c6;
        let __t99 = __s5 * __t4;
        let __t100 = -__c6;
        let __t101 = __qd2 * __qd2;
        let __y1_1 = __t56 * (__t8 - __t10) + __c2 * (-__t13);
        let __y2_1 = __t15 + (2159.0 / 5000.0) * (__qdd2 - __t5 * (-__t6));
        let __t102 = __t5 * __t6;
        let __t103 = __t5 * __t5;
        let __y1_2 = __t56 * (__t9 - __t6 * __t18) + __s2 * __t13;
        let __y2_2 = (2159.0 / 5000.0) * (__qd2 * __t18 - __t103) - __t14;
        let __y2_3 = -__t102;
        let __y1_3 = __s2 * __t9 + __c2 * __t8;
        let __t104 = __t6 * __t6;
        let __y2_4 = __t103 - __t104;
        let __y1_4 = __s2 * (__t10 - __t8) + __c2 * (__t7 + __t9);
        let __y2_5 = __t9 - __t7;
        let __y1_5 = __s2 * (__qdd2 + __t102) + __c2 * (__t101 - __t103);
        let __y2_6 = __t8 + __t10;
        let __y1_6 = __s2 * (__t104 - __t101) + __c2 * (__qdd2 - __t102);
        let __y1_7 = __s2 * __t7 + __c2 * (-__t8);
        let __t105 = -__t20;
        let __t106 = __t17 * __t17;
        let __t107 = __t20 * __t105 - __t106;
        let __y2_13 = __t16 * __t17;
        let __t108 = __y2_13 - __t21;
        let __y1_8 = __t60 * __t108 + __t59 * __t107 + __t61 * (__t23 - __t16 * __t105)
            + __t28 * __t58;
        let __y2_8 = __t29 + __t62 * __t107 + __t63 * __t108;
        let __y3_8 = __t29 + (203.0 / 10000.0) * __t108;
        let __t109 = __t16 * __t20;
        let __y1_9 = __t22 * __t57 + __t58 * (-__t109);
        let __y2_9 = -__y2_13;
        let __t110 = __t17 * __t20;
        let __t111 = __t16 * __t16;
        let __t112 = __t20 * __t20;
        let __y1_10 = __t57 * (__t21 - __y2_13) + __t58 * (__t111 - __t112);
        let __y2_10 = -(__t22 + __t110);
        let __y1_11 = __t57 * (__t23 + __t109) + __t58 * (__t22 - __t110);
        let __y2_11 = -(__t106 - __t111);
        let __y1_12 = __t57 * (__t112 - __t106) + __t58 * (__t21 + __y2_13);
        let __y2_12 = -(__t23 - __t109);
        let __y1_13 = __t57 * __t110 + __t23 * __t58;
        let __t113 = -__t33;
        let __t114 = __t32 * __t32;
        let __t115 = __t33 * __t113 - __t114;
        let __y4_16 = __t30 * __t32;
        let __t116 = __t36 - __t30 * __t113;
        let __t117 = __y4_16 - __t34;
        let __y1_14 = __t68 * __t117 + __t67 * __t115 + __t60 * __t116 + __y4_14 * __t58
            + __t40 * __t66;
        let __t118 = __c4 * __t40;
        let __y2_14 = __t74 * __t117 + __t73 * __t115 + __t63 * __t116 + __t118;
        let __y3_14 = __t118 + __t72 * __t117 + __t71 * __t115
            + (203.0 / 10000.0) * __t116;
        let __t119 = __t30 * __t33;
        let __t120 = __t30 * __t30;
        let __t121 = __t31 * __t32 - __t120;
        let __t122 = __t119 - __t36;
        let __t123 = __t35 - __t31 * __t33;
        let __t124 = -__t39;
        let __y1_15 = __t68 * __t123 + __t67 * __t122 + __t60 * __t121 + __t41 * __t64
            + __t66 * __t124;
        let __t125 = __t2 * __t41 + __c4 * __t124;
        let __y2_15 = __t74 * __t123 + __t73 * __t122 + __t63 * __t121 + __t125;
        let __y3_15 = __t125 + __t72 * __t123 + __t71 * __t122
            + (203.0 / 10000.0) * __t121;
        let __t126 = -__t119;
        let __y1_16 = __t66 * __t126 + __t35 * __t64 + __t58 * __y4_16;
        let __y2_16 = __t2 * __t35 + __c4 * __t126;
        let __y4_20 = -__y4_16;
        let __t127 = __t32 * __t33;
        let __t128 = __t33 * __t33;
        let __t129 = __t120 - __t128;
        let __t130 = __t34 - __y4_16;
        let __y4_17 = __t35 + __t127;
        let __y1_17 = __t66 * __t129 + __t64 * __t130 + __t58 * __y4_17;
        let __y2_17 = __t2 * __t130 + __c4 * __t129;
        let __y4_18 = __t114 - __t120;
        let __t131 = __t36 + __t119;
        let __t132 = __t35 - __t127;
        let __y1_18 = __t66 * __t132 + __t64 * __t131 + __t58 * __y4_18;
        let __y2_18 = __t2 * __t131 + __c4 * __t132;
        let __t133 = __t128 - __t114;
        let __y4_19 = __t36 - __t119;
        let __t134 = __t34 + __y4_16;
        let __y1_19 = __t66 * __t134 + __t64 * __t133 + __t58 * __y4_19;
        let __y2_19 = __t2 * __t133 + __c4 * __t134;
        let __y1_20 = __t36 * __t66 + __t64 * __t127 + __t58 * __y4_20;
        let __y2_20 = __t2 * __t127 + __c4 * __t36;
        let __y5_26 = -__t47;
        let __t135 = -__t46;
        let __t136 = __t44 * __t44;
        let __t137 = __t46 * __t135 - __t136;
        let __y5_29 = __t43 * __t44;
        let __t138 = __t49 - __t43 * __t135;
        let __t139 = __y5_29 - __t47;
        let __t140 = -__y5_21;
        let __y1_21 = __t78 * __t139 + __t77 * __t137 + __t79 * __t138 + __t65 * __t140
            + __y4_14 * __t76;
        let __t141 = __t69 * __t140 + __y4_14 * __t81;
        let __y2_21 = __t83 * __t139 + __t82 * __t137 + __t84 * __t138 + __t141;
        let __y3_21 = __t141 + __t86 * __t139 + __t85 * __t137 + __t87 * __t138;
        let __y4_21 = __c5 * __y4_14;
        let __t142 = -__t44;
        let __t143 = __t43 * __t46;
        let __t144 = __t43 * __t43;
        let __t145 = __t44 * __t142 - __t144;
        let __t146 = __t143 - __t49;
        let __t147 = __t48 - __t46 * __t142;
        let __y5_23 = -__t42;
        let __y1_22 = __t78 * __t147 + __t77 * __t146 + __t79 * __t145 + __y5_21 * __t75
            + __t76 * __y5_23;
        let __t148 = __y5_21 * __t80 + __t81 * __y5_23;
        let __y2_22 = __t83 * __t147 + __t82 * __t146 + __t84 * __t145 + __t148;
        let __y3_22 = __t148 + __t86 * __t147 + __t85 * __t146 + __t87 * __t145;
        let __y4_22 = __s5 * __y5_21 + __c5 * __y5_23;
        let __t149 = -__t43;
        let __t150 = __t44 * __t46;
        let __t151 = __t46 * __t46;
        let __t152 = __t43 * __t149 - __t151;
        let __t153 = __t47 - __t44 * __t149;
        let __t154 = __t150 - __t48;
        let __y1_23 = __t78 * __t152 + __t77 * __t153 + __t79 * __t154 + __t41 * __t75
            + __t42 * __t65;
        let __t155 = __t41 * __t80 + __t42 * __t69;
        let __y2_23 = __t83 * __t152 + __t82 * __t153 + __t84 * __t154 + __t155;
        let __y3_23 = __t155 + __t86 * __t152 + __t85 * __t153 + __t87 * __t154;
        let __y4_23 = __s5 * __t41;
        let __t156 = -__t143;
        let __y1_24 = __t76 * __t156 + __t48 * __t75 + __t65 * __y5_29;
        let __y2_24 = __t81 * __t156 + __t48 * __t80 + __t69 * __y5_29;
        let __y4_24 = __s5 * __t48 + __c5 * __t156;
        let __y5_24 = -__y5_29;
        let __t157 = __t144 - __t151;
        let __t158 = __t47 - __y5_29;
        let __t159 = __t48 + __t150;
        let __y1_25 = __t76 * __t157 + __t75 * __t158 + __t65 * __t159;
        let __y2_25 = __t81 * __t157 + __t80 * __t158 + __t69 * __t159;
        let __y4_25 = __s5 * __t158 + __c5 * __t157;
        let __y5_25 = -__t159;
        let __t160 = -__t150;
        let __y1_26 = __t76 * __t143 + __t75 * __t160 + __t47 * __t65;
        let __y2_26 = __t81 * __t143 + __t80 * __t160 + __t47 * __t69;
        let __y4_26 = __s5 * __t160 + __c5 * __t143;
        let __t161 = __t136 - __t144;
        let __t162 = __t49 + __t143;
        let __t163 = __t48 - __t150;
        let __y1_27 = __t76 * __t163 + __t75 * __t162 + __t65 * __t161;
        let __y2_27 = __t81 * __t163 + __t80 * __t162 + __t69 * __t161;
        let __y4_27 = __s5 * __t162 + __c5 * __t163;
        let __y5_27 = -__t161;
        let __t164 = __t151 - __t136;
        let __t165 = __t49 - __t143;
        let __t166 = __t47 + __y5_29;
        let __y1_28 = __t76 * __t166 + __t75 * __t164 + __t65 * __t165;
        let __y2_28 = __t81 * __t166 + __t80 * __t164 + __t69 * __t165;
        let __y4_28 = __s5 * __t164 + __c5 * __t166;
        let __y5_28 = -__t165;
        let __y1_29 = __t49 * __t76 + __t75 * __t150 + __t65 * __y5_24;
        let __y2_29 = __t49 * __t81 + __t80 * __t150 + __t69 * __y5_24;
        let __y4_29 = __s5 * __t150 + __c5 * __t49;
        let __t167 = -__t51;
        let __t168 = __t52 * __t52;
        let __t169 = __t51 * __t167 - __t168;
        let __t170 = __t50 * __t52;
        let __t171 = __y6_36 - __t50 * __t167;
        let __t172 = __t170 - __t54;
        let __y1_30 = __t78 * __t172 + __t90 * __t169 + __t91 * __t171 + __t89 * __t140
            + __y6_30 * __t76;
        let __t173 = __t93 * __t140 + __y6_30 * __t81;
        let __y2_30 = __t83 * __t172 + __t94 * __t169 + __t95 * __t171 + __t173;
        let __y3_30 = __t173 + __t86 * __t172 + __t96 * __t169 + __t97 * __t171;
        let __y4_30 = __t99 * __t140 + __c5 * __y6_30;
        let __y5_30 = __t100 * __t140;
        let __t174 = -__t52;
        let __t175 = __t50 * __t51;
        let __t176 = __t50 * __t50;
        let __t177 = __t52 * __t174 - __t176;
        let __t178 = __t175 - __y6_36;
        let __t179 = __t53 - __t51 * __t174;
        let __y6_31 = -(__c6 * __t42 + __s6 * __y4_14);
        let __y1_31 = __t78 * __t179 + __t90 * __t178 + __t91 * __t177 + __y5_21 * __t88
            + __t76 * __y6_31;
        let __t180 = __y5_21 * __t92 + __t81 * __y6_31;
        let __y2_31 = __t83 * __t179 + __t94 * __t178 + __t95 * __t177 + __t180;
        let __y3_31 = __t180 + __t86 * __t179 + __t96 * __t178 + __t97 * __t177;
        let __y4_31 = __y5_21 * __t98 + __c5 * __y6_31;
        let __y5_31 = __t4 * __y5_21;
        let __y6_32 = -__t175;
        let __y1_32 = __t76 * __y6_32 + __t53 * __t88 + __t89 * __t170;
        let __y2_32 = __t81 * __y6_32 + __t53 * __t92 + __t93 * __t170;
        let __y4_32 = __c5 * __y6_32 + __t53 * __t98 + __t99 * __t170;
        let __y5_32 = __t4 * __t53 + __t100 * __t170;
        let __t181 = -__t170;
        let __t182 = __t51 * __t52;
        let __t183 = __t51 * __t51;
        let __y6_33 = __t176 - __t183;
        let __t184 = __t54 - __t170;
        let __t185 = __t53 + __t182;
        let __y1_33 = __t76 * __y6_33 + __t88 * __t184 + __t89 * __t185;
        let __y2_33 = __t81 * __y6_33 + __t92 * __t184 + __t93 * __t185;
        let __y4_33 = __c5 * __y6_33 + __t98 * __t184 + __t99 * __t185;
        let __y5_33 = __t4 * __t184 + __t100 * __t185;
        let __t186 = __t168 - __t176;
        let __t187 = __y6_36 + __t175;
        let __y6_34 = __t53 - __t182;
        let __y1_34 = __t76 * __y6_34 + __t88 * __t187 + __t89 * __t186;
        let __y2_34 = __t81 * __y6_34 + __t92 * __t187 + __t93 * __t186;
        let __y4_34 = __c5 * __y6_34 + __t98 * __t187 + __t99 * __t186;
        let __y5_34 = __t4 * __t187 + __t100 * __t186;
        let __t188 = __t183 - __t168;
        let __t189 = __y6_36 - __t175;
        let __y6_35 = __t54 + __t170;
        let __y1_35 = __t76 * __y6_35 + __t88 * __t188 + __t89 * __t189;
        let __y2_35 = __t81 * __y6_35 + __t92 * __t188 + __t93 * __t189;
        let __y4_35 = __c5 * __y6_35 + __t98 * __t188 + __t99 * __t189;
        let __y5_35 = __t4 * __t188 + __t100 * __t189;
        let __y1_36 = __y6_36 * __t76 + __t88 * __t182 + __t89 * __t181;
        let __y2_36 = __y6_36 * __t81 + __t92 * __t182 + __t93 * __t181;
        let __y4_36 = __c5 * __y6_36 + __t98 * __t182 + __t99 * __t181;
        let __y5_36 = __t4 * __t182 + __t100 * __t181;
        let __y3_1 = 0.0;
        ::planar_arm::__private::columns([
            [__y1_1, __y2_1, __y3_1, __y3_1, __y3_1, __y3_1],
            [__y1_2, __y2_2, __y3_1, __y3_1, __y3_1, __y3_1],
            [__y1_3, __y2_3, __y3_1, __y3_1, __y3_1, __y3_1],
            [__y1_4, __y2_4, __y3_1, __y3_1, __y3_1, __y3_1],
            [__y1_5, __y2_5, __y3_1, __y3_1, __y3_1, __y3_1],
            [__y1_6, __y2_6, __y3_1, __y3_1, __y3_1, __y3_1],
            [__y1_7, __qdd2, __y3_1, __y3_1, __y3_1, __y3_1],
            [__y1_8, __y2_8, __y3_8, __y3_1, __y3_1, __y3_1],
            [__y1_9, __y2_9, __y2_9, __y3_1, __y3_1, __y3_1],
            [__y1_10, __y2_10, __y2_10, __y3_1, __y3_1, __y3_1],
            [__y1_11, __y2_11, __y2_11, __y3_1, __y3_1, __y3_1],
            [__y1_12, __y2_12, __y2_12, __y3_1, __y3_1, __y3_1],
            [__y1_13, __y2_13, __y2_13, __y3_1, __y3_1, __y3_1],
            [__y1_14, __y2_14, __y3_14, __y4_14, __y3_1, __y3_1],
            [__y1_15, __y2_15, __y3_15, __y3_1, __y3_1, __y3_1],
            [__y1_16, __y2_16, __y2_16, __y4_16, __y3_1, __y3_1],
            [__y1_17, __y2_17, __y2_17, __y4_17, __y3_1, __y3_1],
            [__y1_18, __y2_18, __y2_18, __y4_18, __y3_1, __y3_1],
            [__y1_19, __y2_19, __y2_19, __y4_19, __y3_1, __y3_1],
            [__y1_20, __y2_20, __y2_20, __y4_20, __y3_1, __y3_1],
            [__y1_21, __y2_21, __y3_21, __y4_21, __y5_21, __y3_1],
            [__y1_22, __y2_22, __y3_22, __y4_22, __y3_1, __y3_1],
            [__y1_23, __y2_23, __y3_23, __y4_23, __y5_23, __y3_1],
            [__y1_24, __y2_24, __y2_24, __y4_24, __y5_24, __y3_1],
            [__y1_25, __y2_25, __y2_25, __y4_25, __y5_25, __y3_1],
            [__y1_26, __y2_26, __y2_26, __y4_26, __y5_26, __y3_1],
            [__y1_27, __y2_27, __y2_27, __y4_27, __y5_27, __y3_1],
            [__y1_28, __y2_28, __y2_28, __y4_28, __y5_28, __y3_1],
            [__y1_29, __y2_29, __y2_29, __y4_29, __y5_29, __y3_1],
            [__y1_30, __y2_30, __y3_30, __y4_30, __y5_30, __y6_30],
            [__y1_31, __y2_31, __y3_31, __y4_31, __y5_31, __y6_31],
            [__y1_32, __y2_32, __y2_32, __y4_32, __y5_32, __y6_32],
            [__y1_33, __y2_33, __y2_33, __y4_33, __y5_33, __y6_33],
            [__y1_34, __y2_34, __y2_34, __y4_34, __y5_34, __y6_34],
            [__y1_35, __y2_35, __y2_35, __y4_35, __y5_35, __y6_35],
            [__y1_36, __y2_36, __y2_36, __y4_36, __y5_36, __y6_36],
        ])
    }
    #[doc(hidden)]
    #[inline(always)]
    fn __base_regressor_packed<__L: ::planar_arm::__private::Lanes>(
        &self,
        __lanes: __L,
        __q: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
        __qdd: &::planar_arm::nalgebra::SVector<::core::primitive::f64, 6>,
    ) -> ::planar_arm::nalgebra::SMatrix<::core::primitive::f64, 6, 36> {
        let [_, __q2, __q3, __q4, __q5, __q6] = ::planar_arm::__private::unpack(__q);
        let [__qd1, __qd2, __qd3, __qd4, __qd5, __qd6] = ::planar_arm::__private::unpack(
            __qd,
        );
        let [__qdd1, __qdd2, __qdd3, __qdd4, __qdd5, __qdd6] = ::planar_arm::__private::unpack(
            __qdd,
        );
        let [(__s2, __c2), (__s3, __c3), (__s4, __c4), (__s5, __c5), (__s6, __c6)] = ::planar_arm::__private::sin_cos([
            __q2,
            __q3,
            __q4,
            __q5,
            __q6,
        ]);
        let __v5 = -__s3;
        let __v10 = -__s4;
        let __v13 = -__s5;
        let __v16 = -__s6;
        let __t1 = __s2 * __qd1;
        let __t2 = __c2 * __qd1;
        let __v37 = __qd2 * __t2;
        let __v26 = __qd2 * __t1;
        let __v38 = -__v26;
        let __v25 = __s2 * __qdd1 + __v37;
        let __t3 = __c2 * __qdd1 - __v26;
        let __t4 = (2159.0 / 5000.0) * __qd2;
        let __t5 = -((2159.0 / 5000.0) * __t2);
        let __v23 = __t1 * __t4 - (2159.0 / 5000.0) * __t3;
        let __t6 = (981.0 / 100.0) * __s2 + __t2 * __t5 - __qd2 * __t4;
        let __v20 = (981.0 / 100.0) * __c2 + (2159.0 / 5000.0) * __qdd2 - __t1 * __t5;
        let __v19 = -__v23;
        let __t7 = __c3 * __t1 + __s3 * __t2;
        let __t8 = __v5 * __t1 + __c3 * __t2;
        let __t9 = -__qd2;
        let __t10 = -__qd3;
        let __t11 = __t9 - __qd3;
        let __t12 = -__qdd2 - __qdd3;
        let __v45 = __c3 * __v25 + __s3 * __t3 - __t8 * __t10;
        let __v59 = __v5 * __v25 + __c3 * __t3 + __t7 * __t10;
        let __t13 = -((-(3001.0 / 20000.0)) * __t8);
        let __t14 = (203.0 / 10000.0) * __t8;
        let __t15 = (-(3001.0 / 20000.0)) * __t7 - (203.0 / 10000.0) * __t11;
        let __t16 = __c3 * __t6 + __s3 * __v20 + __t11 * __t15 - __t8 * __t14
            - (-(3001.0 / 20000.0)) * __v59;
        let __v44 = __t8 * __t13 - __t7 * __t15 + (203.0 / 10000.0) * __v59 - __v23;
        let __t17 = __v5 * __t6 + __c3 * __v20 + __t7 * __t14 - __t11 * __t13
            + (-(3001.0 / 20000.0)) * __v45 - (203.0 / 10000.0) * __t12;
        let __t18 = __c4 * __t7 + __s4 * __t11;
        let __t19 = __v10 * __t7 + __c4 * __t11;
        let __t20 = -__t19;
        let __t21 = __t8 + __qd4;
        let __t22 = __v59 + __qdd4;
        let __v70 = __c4 * __v45 + __s4 * __t12 - __qd4 * __t20;
        let __v84 = __qd4 * __t18 - (__v10 * __v45 + __c4 * __t12);
        let __t23 = -((2159.0 / 5000.0) * __t20);
        let __t24 = (2159.0 / 5000.0) * __t18;
        let __t25 = __c4 * __t16 + __s4 * __v44 + __t21 * __t24
            - (2159.0 / 5000.0) * __v84;
        let __v64 = __t17 + __t20 * __t23 - __t18 * __t24;
        let __v68 = (2159.0 / 5000.0) * __v70 - __t21 * __t23
            - (__v10 * __t16 + __c4 * __v44);
        let __v97 = __c5 * __t25 + __s5 * __v64;
        let __v92 = __v13 * __t25 + __c5 * __v64;
        let __v63 = -__v68;
        let __t26 = __c5 * __t18 + __s5 * __t21;
        let __t27 = __v13 * __t18 + __c5 * __t21;
        let __t28 = -__qd5;
        let __t29 = __t19 - __qd5;
        let __v105 = -__v84 - __qdd5;
        let __v98 = __c5 * __v70 + __s5 * __t22 - __t27 * __t28;
        let __v115 = __v13 * __v70 + __c5 * __t22 + __t26 * __t28;
        let __v119 = __v16 * __v97 + __c6 * __v63;
        let __t30 = __c6 * __t26 + __s6 * __t29;
        let __t31 = __v16 * __t26 + __c6 * __t29;
        let __t32 = __t27 + __qd6;
        let __v138 = __v115 + __qdd6;
        let __v124 = __c6 * __v98 + __s6 * __v105 + __qd6 * __t31;
        let __t33 = __v16 * __v98 + __c6 * __v105 - __qd6 * __t30;
        let __t34 = __qd2 * __qd2;
        let __v17 = __qdd2 - __t1 * (-__t2);
        let __v18 = __v26 - __t3;
        let __t35 = __t1 * __t2;
        let __t36 = __t1 * __t1;
        let __v21 = __qd2 * __t9 - __t36;
        let __v22 = __v25 - __t2 * __t9;
        let __v24 = -__t6;
        let __v27 = -__t35;
        let __t37 = __t2 * __t2;
        let __v30 = __t36 - __t37;
        let __v28 = __t3 - __v26;
        let __v29 = __v37 + __v25;
        let __v32 = __t34 - __t36;
        let __v31 = __qdd2 + __t35;
        let __v33 = __v25 - __v37;
        let __v34 = __t37 - __t34;
        let __v35 = __qdd2 - __t35;
        let __v36 = __v26 + __t3;
        let __t38 = -__t11;
        let __t39 = __t8 * __t8;
        let __v40 = __t11 * __t38 - __t39;
        let __v46 = __t7 * __t8;
        let __v41 = __v59 - __t7 * __t38;
        let __v42 = __v46 - __t12;
        let __v43 = -__t17;
        let __t40 = __t7 * __t11;
        let __v47 = -__t40;
        let __v58 = -__v46;
        let __v57 = __t8 * __t11;
        let __t41 = __t7 * __t7;
        let __t42 = __t11 * __t11;
        let __v50 = __t41 - __t42;
        let __v48 = __t12 - __v46;
        let __v49 = __v45 + __v57;
        let __v52 = __t39 - __t41;
        let __v51 = __v59 + __t40;
        let __v53 = __v45 - __v57;
        let __v54 = __t42 - __t39;
        let __v55 = __v59 - __t40;
        let __v56 = __t12 + __v46;
        let __t43 = -__t21;
        let __t44 = __t20 * __t20;
        let __v60 = __t21 * __t43 - __t44;
        let __v71 = __t18 * __t20;
        let __v61 = __v84 - __t18 * __t43;
        let __v62 = __v71 - __t22;
        let __t45 = __t18 * __t21;
        let __t46 = __t18 * __t18;
        let __v66 = __t19 * __t20 - __t46;
        let __v65 = __t45 - __v84;
        let __v67 = __v70 - __t19 * __t21;
        let __v69 = -__t25;
        let __v72 = -__t45;
        let __v83 = -__v71;
        let __v82 = __t20 * __t21;
        let __t47 = __t21 * __t21;
        let __v75 = __t46 - __t47;
        let __v73 = __t22 - __v71;
        let __v74 = __v70 + __v82;
        let __v77 = __t44 - __t46;
        let __v76 = __v84 + __t45;
        let __v78 = __v70 - __v82;
        let __v79 = __t47 - __t44;
        let __v80 = __v84 - __t45;
        let __v81 = __t22 + __v71;
        let __t48 = -__t29;
        let __t49 = __t27 * __t27;
        let __v85 = __t29 * __t48 - __t49;
        let __v99 = __t26 * __t27;
        let __v86 = __v115 - __t26 * __t48;
        let __v87 = __v99 - __v105;
        let __v88 = -__v92;
        let __t50 = -__t27;
        let __v106 = __t26 * __t29;
        let __t51 = __t26 * __t26;
        let __v90 = __t27 * __t50 - __t51;
        let __v89 = __v106 - __v115;
        let __v91 = __v98 - __t29 * __t50;
        let __v93 = -__v97;
        let __t52 = -__t26;
        let __v113 = __t27 * __t29;
        let __t53 = __t29 * __t29;
        let __v96 = __t26 * __t52 - __t53;
        let __v94 = __v105 - __t27 * __t52;
        let __v95 = __v113 - __v98;
        let __v100 = -__v106;
        let __v114 = -__v99;
        let __v103 = __t51 - __t53;
        let __v101 = __v105 - __v99;
        let __v102 = __v98 + __v113;
        let __v104 = -__v113;
        let __v108 = __t49 - __t51;
        let __v107 = __v115 + __v106;
        let __v109 = __v98 - __v113;
        let __v110 = __t53 - __t49;
        let __v111 = __v115 - __v106;
        let __v112 = __v105 + __v99;
        let __t54 = -__t31;
        let __t55 = __t32 * __t32;
        let __v116 = __t31 * __t54 - __t55;
        let __v125 = __t30 * __t32;
        let __v117 = __v138 - __t30 * __t54;
        let __v118 = __v125 - __t33;
        let __t56 = -__t32;
        let __t57 = __t30 * __t31;
        let __t58 = __t30 * __t30;
        let __v121 = __t32 * __t56 - __t58;
        let __v120 = __t57 - __v138;
        let __v122 = __v124 - __t31 * __t56;
        let __v123 = -(__c6 * __v97 + __s6 * __v63);
        let __v126 = -__t57;
        let __v137 = -__v125;
        let __v136 = __t31 * __t32;
        let __t59 = __t31 * __t31;
        let __v129 = __t58 - __t59;
        let __v127 = __t33 - __v125;
        let __v128 = __v124 + __v136;
        let __v131 = __t55 - __t58;
        let __v130 = __v138 + __t57;
        let __v132 = __v124 - __v136;
        let __v133 = __t59 - __t55;
        let __v134 = __v138 - __t57;
        let __v135 = __t33 + __v125;
        let __v2 = (2159.0 / 5000.0);
        let __v6 = (-(3001.0 / 20000.0));
        let __v7 = (203.0 / 10000.0);
        let __lane0 = __lanes.constant([1.0, 0.0, 0.0, 0.0]);
        let __lane1 = __lanes.constant([0.0, 1.0, 0.0, 0.0]);
        let __lane2 = __lanes.mul(__lane0, __lanes.splat(__s2));
        let __lane3 = __lanes.mul(__lane0, __lanes.splat(__c2));
        let __lane4 = __lanes.mul(__lane1, __lanes.splat(__v2));
        let __lane5 = __lanes.mul(__lane3, __lanes.splat(__v2));
        let __lane6 = __lanes.neg(__lane5);
        let __lane7 = __lanes.constant([0.0, 0.0, 1.0, 0.0]);
        let __lane8 = __lanes.mul(__lane2, __lanes.splat(__c3));
        let __lane10 = __lanes.mul_add(__lane3, __s3, __lane8);
        let __lane11 = __lanes.mul(__lane2, __lanes.splat(__v5));
        let __lane13 = __lanes.mul_add(__lane3, __c3, __lane11);
        let __lane14 = __lanes.neg(__lane1);
        let __lane15 = __lanes.mul(__lane4, __lanes.splat(__s3));
        let __lane17 = __lanes.sub(__lane14, __lane7);
        let __lane20 = __lanes.mul(__lane10, __lanes.splat(__v6));
        let __lane22 = __lanes.neg_mul_add(__lane17, __v7, __lane20);
        let __lane23 = __lanes.neg_mul_add(__lane13, __v6, __lane15);
        let __lane24 = __lanes.mul_add(__lane13, __v7, __lane5);
        let __lane25 = __lanes.mul_add(__lane4, __c3, __lane22);
        let __lane26 = __lanes.constant([0.0, 0.0, 0.0, 1.0]);
        let __lane27 = __lanes.mul(__lane10, __lanes.splat(__c4));
        let __lane29 = __lanes.mul_add(__lane17, __s4, __lane27);
        let __lane30 = __lanes.mul(__lane10, __lanes.splat(__v10));
        let __lane32 = __lanes.mul_add(__lane17, __c4, __lane30);
        let __lane33 = __lanes.neg(__lane32);
        let __lane34 = __lanes.mul(__lane23, __lanes.splat(__c4));
        let __lane36 = __lanes.mul_add(__lane24, __s4, __lane34);
        let __lane37 = __lanes.mul(__lane23, __lanes.splat(__v10));
        let __lane39 = __lanes.mul_add(__lane24, __c4, __lane37);
        let __lane40 = __lanes.add(__lane13, __lane26);
        let __lane43 = __lanes.neg_mul_add(__lane33, __v2, __lane36);
        let __lane44 = __lanes.mul_sub(__lane29, __v2, __lane39);
        let __lane45 = __lanes.mul(__lane29, __lanes.splat(__c5));
        let __lane47 = __lanes.mul_add(__lane40, __s5, __lane45);
        let __lane48 = __lanes.mul(__lane29, __lanes.splat(__v13));
        let __lane50 = __lanes.mul_add(__lane40, __c5, __lane48);
        let __lane51 = __lanes.mul(__lane43, __lanes.splat(__c5));
        let __lane53 = __lanes.mul_add(__lane25, __s5, __lane51);
        let __lane54 = __lanes.mul(__lane43, __lanes.splat(__v13));
        let __lane56 = __lanes.mul_add(__lane25, __c5, __lane54);
        let __lane57 = __lanes.neg(__lane44);
        let __lane58 = __lanes.mul(__lane47, __lanes.splat(__c6));
        let __lane60 = __lanes.mul_add(__lane32, __s6, __lane58);
        let __lane61 = __lanes.mul(__lane47, __lanes.splat(__v16));
        let __lane63 = __lanes.mul_add(__lane32, __c6, __lane61);
        let __lane64 = __lanes.mul(__lane53, __lanes.splat(__c6));
        let __lane66 = __lanes.mul_add(__lane57, __s6, __lane64);
        let __lane67 = __lanes.mul(__lane53, __lanes.splat(__v16));
        let __lane69 = __lanes.mul_add(__lane57, __c6, __lane67);
        let __lane70 = __lanes.mul(__lane4, __lanes.splat(__v17));
        let __lane72 = __lanes.mul_add(__lane6, __v18, __lane70);
        let __lane73 = __lanes.mul(__lane3, __lanes.splat(__v19));
        let __lane75 = __lanes.mul_add(__lane1, __v20, __lane73);
        let __lane76 = __lanes.add(__lane72, __lane75);
        let __lane77 = __lanes.mul(__lane4, __lanes.splat(__v21));
        let __lane79 = __lanes.mul_add(__lane6, __v22, __lane77);
        let __lane80 = __lanes.mul(__lane2, __lanes.splat(__v23));
        let __lane82 = __lanes.mul_add(__lane1, __v24, __lane80);
        let __lane83 = __lanes.add(__lane79, __lane82);
        let __lane84 = __lanes.mul(__lane2, __lanes.splat(__v25));
        let __lane87 = __lanes.mul_add(__lane3, __v26, __lane84);
        let __lane88 = __lanes.mul_add(__lane1, __v27, __lane87);
        let __lane89 = __lanes.mul(__lane2, __lanes.splat(__v28));
        let __lane92 = __lanes.mul_add(__lane3, __v29, __lane89);
        let __lane93 = __lanes.mul_add(__lane1, __v30, __lane92);
        let __lane94 = __lanes.mul(__lane2, __lanes.splat(__v31));
        let __lane97 = __lanes.mul_add(__lane3, __v32, __lane94);
        let __lane98 = __lanes.mul_add(__lane1, __v33, __lane97);
        let __lane99 = __lanes.mul(__lane2, __lanes.splat(__v34));
        let __lane102 = __lanes.mul_add(__lane3, __v35, __lane99);
        let __lane103 = __lanes.mul_add(__lane1, __v36, __lane102);
        let __lane104 = __lanes.mul(__lane2, __lanes.splat(__v37));
        let __lane107 = __lanes.mul_add(__lane3, __v38, __lane104);
        let __lane108 = __lanes.mul_add(__lane1, __qdd2, __lane107);
        let __lane109 = __lanes.mul(__lane23, __lanes.splat(__v40));
        let __lane112 = __lanes.mul_add(__lane24, __v41, __lane109);
        let __lane113 = __lanes.mul_add(__lane25, __v42, __lane112);
        let __lane114 = __lanes.mul(__lane17, __lanes.splat(__v43));
        let __lane116 = __lanes.mul_add(__lane13, __v44, __lane114);
        let __lane117 = __lanes.add(__lane113, __lane116);
        let __lane118 = __lanes.mul(__lane10, __lanes.splat(__v45));
        let __lane121 = __lanes.mul_add(__lane17, __v46, __lane118);
        let __lane122 = __lanes.mul_add(__lane13, __v47, __lane121);
        let __lane123 = __lanes.mul(__lane10, __lanes.splat(__v48));
        let __lane126 = __lanes.mul_add(__lane17, __v49, __lane123);
        let __lane127 = __lanes.mul_add(__lane13, __v50, __lane126);
        let __lane128 = __lanes.mul(__lane10, __lanes.splat(__v51));
        let __lane131 = __lanes.mul_add(__lane17, __v52, __lane128);
        let __lane132 = __lanes.mul_add(__lane13, __v53, __lane131);
        let __lane133 = __lanes.mul(__lane10, __lanes.splat(__v54));
        let __lane136 = __lanes.mul_add(__lane17, __v55, __lane133);
        let __lane137 = __lanes.mul_add(__lane13, __v56, __lane136);
        let __lane138 = __lanes.mul(__lane10, __lanes.splat(__v57));
        let __lane141 = __lanes.mul_add(__lane17, __v58, __lane138);
        let __lane142 = __lanes.mul_add(__lane13, __v59, __lane141);
        let __lane143 = __lanes.mul(__lane43, __lanes.splat(__v60));
        let __lane146 = __lanes.mul_add(__lane25, __v61, __lane143);
        let __lane147 = __lanes.mul_add(__lane44, __v62, __lane146);
        let __lane148 = __lanes.mul(__lane40, __lanes.splat(__v63));
        let __lane150 = __lanes.mul_add(__lane33, __v64, __lane148);
        let __lane151 = __lanes.add(__lane147, __lane150);
        let __lane152 = __lanes.mul(__lane43, __lanes.splat(__v65));
        let __lane155 = __lanes.mul_add(__lane25, __v66, __lane152);
        let __lane156 = __lanes.mul_add(__lane44, __v67, __lane155);
        let __lane157 = __lanes.mul(__lane29, __lanes.splat(__v68));
        let __lane159 = __lanes.mul_add(__lane33, __v69, __lane157);
        let __lane160 = __lanes.add(__lane156, __lane159);
        let __lane161 = __lanes.mul(__lane29, __lanes.splat(__v70));
        let __lane164 = __lanes.mul_add(__lane40, __v71, __lane161);
        let __lane165 = __lanes.mul_add(__lane33, __v72, __lane164);
        let __lane166 = __lanes.mul(__lane29, __lanes.splat(__v73));
        let __lane169 = __lanes.mul_add(__lane40, __v74, __lane166);
        let __lane170 = __lanes.mul_add(__lane33, __v75, __lane169);
        let __lane171 = __lanes.mul(__lane29, __lanes.splat(__v76));
        let __lane174 = __lanes.mul_add(__lane40, __v77, __lane171);
        let __lane175 = __lanes.mul_add(__lane33, __v78, __lane174);
        let __lane176 = __lanes.mul(__lane29, __lanes.splat(__v79));
        let __lane179 = __lanes.mul_add(__lane40, __v80, __lane176);
        let __lane180 = __lanes.mul_add(__lane33, __v81, __lane179);
        let __lane181 = __lanes.mul(__lane29, __lanes.splat(__v82));
        let __lane184 = __lanes.mul_add(__lane40, __v83, __lane181);
        let __lane185 = __lanes.mul_add(__lane33, __v84, __lane184);
        let __lane186 = __lanes.mul(__lane53, __lanes.splat(__v85));
        let __lane189 = __lanes.mul_add(__lane57, __v86, __lane186);
        let __lane190 = __lanes.mul_add(__lane56, __v87, __lane189);
        let __lane191 = __lanes.mul(__lane32, __lanes.splat(__v88));
        let __lane193 = __lanes.mul_add(__lane50, __v63, __lane191);
        let __lane194 = __lanes.add(__lane190, __lane193);
        let __lane195 = __lanes.mul(__lane53, __lanes.splat(__v89));
        let __lane198 = __lanes.mul_add(__lane57, __v90, __lane195);
        let __lane199 = __lanes.mul_add(__lane56, __v91, __lane198);
        let __lane200 = __lanes.mul(__lane47, __lanes.splat(__v92));
        let __lane202 = __lanes.mul_add(__lane50, __v93, __lane200);
        let __lane203 = __lanes.add(__lane199, __lane202);
        let __lane204 = __lanes.mul(__lane53, __lanes.splat(__v94));
        let __lane207 = __lanes.mul_add(__lane57, __v95, __lane204);
        let __lane208 = __lanes.mul_add(__lane56, __v96, __lane207);
        let __lane209 = __lanes.mul(__lane47, __lanes.splat(__v68));
        let __lane211 = __lanes.mul_add(__lane32, __v97, __lane209);
        let __lane212 = __lanes.add(__lane208, __lane211);
        let __lane213 = __lanes.mul(__lane47, __lanes.splat(__v98));
        let __lane216 = __lanes.mul_add(__lane32, __v99, __lane213);
        let __lane217 = __lanes.mul_add(__lane50, __v100, __lane216);
        let __lane218 = __lanes.mul(__lane47, __lanes.splat(__v101));
        let __lane221 = __lanes.mul_add(__lane32, __v102, __lane218);
        let __lane222 = __lanes.mul_add(__lane50, __v103, __lane221);
        let __lane223 = __lanes.mul(__lane47, __lanes.splat(__v104));
        let __lane226 = __lanes.mul_add(__lane32, __v105, __lane223);
        let __lane227 = __lanes.mul_add(__lane50, __v106, __lane226);
        let __lane228 = __lanes.mul(__lane47, __lanes.splat(__v107));
        let __lane231 = __lanes.mul_add(__lane32, __v108, __lane228);
        let __lane232 = __lanes.mul_add(__lane50, __v109, __lane231);
        let __lane233 = __lanes.mul(__lane47, __lanes.splat(__v110));
        let __lane236 = __lanes.mul_add(__lane32, __v111, __lane233);
        let __lane237 = __lanes.mul_add(__lane50, __v112, __lane236);
        let __lane238 = __lanes.mul(__lane47, __lanes.splat(__v113));
        let __lane241 = __lanes.mul_add(__lane32, __v114, __lane238);
        let __lane242 = __lanes.mul_add(__lane50, __v115, __lane241);
        let __lane243 = __lanes.mul(__lane66, __lanes.splat(__v116));
        let __lane246 = __lanes.mul_add(__lane69, __v117, __lane243);
        let __lane247 = __lanes.mul_add(__lane56, __v118, __lane246);
        let __lane248 = __lanes.mul(__lane63, __lanes.splat(__v88));
        let __lane250 = __lanes.mul_add(__lane50, __v119, __lane248);
        let __lane251 = __lanes.add(__lane247, __lane250);
        let __lane252 = __lanes.mul(__lane66, __lanes.splat(__v120));
        let __lane255 = __lanes.mul_add(__lane69, __v121, __lane252);
        let __lane256 = __lanes.mul_add(__lane56, __v122, __lane255);
        let __lane257 = __lanes.mul(__lane60, __lanes.splat(__v92));
        let __lane259 = __lanes.mul_add(__lane50, __v123, __lane257);
        let __lane260 = __lanes.add(__lane256, __lane259);
        let __lane261 = __lanes.mul(__lane60, __lanes.splat(__v124));
        let __lane264 = __lanes.mul_add(__lane63, __v125, __lane261);
        let __lane265 = __lanes.mul_add(__lane50, __v126, __lane264);
        let __lane266 = __lanes.mul(__lane60, __lanes.splat(__v127));
        let __lane269 = __lanes.mul_add(__lane63, __v128, __lane266);
        let __lane270 = __lanes.mul_add(__lane50, __v129, __lane269);
        let __lane271 = __lanes.mul(__lane60, __lanes.splat(__v130));
        let __lane274 = __lanes.mul_add(__lane63, __v131, __lane271);
        let __lane275 = __lanes.mul_add(__lane50, __v132, __lane274);
        let __lane276 = __lanes.mul(__lane60, __lanes.splat(__v133));
        let __lane279 = __lanes.mul_add(__lane63, __v134, __lane276);
        let __lane280 = __lanes.mul_add(__lane50, __v135, __lane279);
        let __lane281 = __lanes.mul(__lane60, __lanes.splat(__v136));
        let __lane284 = __lanes.mul_add(__lane63, __v137, __lane281);
        let __lane285 = __lanes.mul_add(__lane50, __v138, __lane284);
        let __lane286 = __lanes.neg(__lane0);
        let __lane287 = __lanes.mul(__lane286, __lanes.splat(__s6));
        let __lane288 = __lanes.mul(__lane286, __lanes.splat(__c6));
        let __lane289 = __lanes.mul(__lane286, __lanes.splat(__v88));
        let __lane290 = __lanes.mul(__lane286, __lanes.splat(__v97));
        let __lane291 = __lanes.mul(__lane286, __lanes.splat(__v99));
        let __lane292 = __lanes.mul(__lane286, __lanes.splat(__v102));
        let __lane293 = __lanes.mul(__lane286, __lanes.splat(__v105));
        let __lane294 = __lanes.mul(__lane286, __lanes.splat(__v108));
        let __lane295 = __lanes.mul(__lane286, __lanes.splat(__v111));
        let __lane296 = __lanes.mul(__lane286, __lanes.splat(__v114));
        let __lane297 = __lanes.mul(__lane288, __lanes.splat(__v88));
        let __lane299 = __lanes.mul_add(__lane1, __v119, __lane297);
        let __lane300 = __lanes.mul(__lane287, __lanes.splat(__v92));
        let __lane302 = __lanes.mul_add(__lane1, __v123, __lane300);
        let __lane303 = __lanes.mul(__lane287, __lanes.splat(__v124));
        let __lane306 = __lanes.mul_add(__lane288, __v125, __lane303);
        let __lane307 = __lanes.mul_add(__lane1, __v126, __lane306);
        let __lane308 = __lanes.mul(__lane287, __lanes.splat(__v127));
        let __lane311 = __lanes.mul_add(__lane288, __v128, __lane308);
        let __lane312 = __lanes.mul_add(__lane1, __v129, __lane311);
        let __lane313 = __lanes.mul(__lane287, __lanes.splat(__v130));
        let __lane316 = __lanes.mul_add(__lane288, __v131, __lane313);
        let __lane317 = __lanes.mul_add(__lane1, __v132, __lane316);
        let __lane318 = __lanes.mul(__lane287, __lanes.splat(__v133));
        let __lane321 = __lanes.mul_add(__lane288, __v134, __lane318);
        let __lane322 = __lanes.mul_add(__lane1, __v135, __lane321);
        let __lane323 = __lanes.mul(__lane287, __lanes.splat(__v136));
        let __lane326 = __lanes.mul_add(__lane288, __v137, __lane323);
        let __lane327 = __lanes.mul_add(__lane1, __v138, __lane326);
        let __lane76_0 = __lanes.lanes(__lane76)[0];
        let __lane83_0 = __lanes.lanes(__lane83)[0];
        let __lane88_0 = __lanes.lanes(__lane88)[0];
        let __lane93_0 = __lanes.lanes(__lane93)[0];
        let __lane98_0 = __lanes.lanes(__lane98)[0];
        let __lane103_0 = __lanes.lanes(__lane103)[0];
        let __lane108_0 = __lanes.lanes(__lane108)[0];
        let __lane117_0 = __lanes.lanes(__lane117)[0];
        let __lane122_0 = __lanes.lanes(__lane122)[0];
        let __lane127_0 = __lanes.lanes(__lane127)[0];
        let __lane132_0 = __lanes.lanes(__lane132)[0];
        let __lane137_0 = __lanes.lanes(__lane137)[0];
        let __lane142_0 = __lanes.lanes(__lane142)[0];
        let __lane151_0 = __lanes.lanes(__lane151)[0];
        let __lane160_0 = __lanes.lanes(__lane160)[0];
        let __lane165_0 = __lanes.lanes(__lane165)[0];
        let __lane170_0 = __lanes.lanes(__lane170)[0];
        let __lane175_0 = __lanes.lanes(__lane175)[0];
        let __lane180_0 = __lanes.lanes(__lane180)[0];
        let __lane185_0 = __lanes.lanes(__lane185)[0];
        let __lane194_0 = __lanes.lanes(__lane194)[0];
        let __lane203_0 = __lanes.lanes(__lane203)[0];
        let __lane212_0 = __lanes.lanes(__lane212)[0];
        let __lane217_0 = __lanes.lanes(__lane217)[0];
        let __lane222_0 = __lanes.lanes(__lane222)[0];
        let __lane227_0 = __lanes.lanes(__lane227)[0];
        let __lane232_0 = __lanes.lanes(__lane232)[0];
        let __lane237_0 = __lanes.lanes(__lane237)[0];
        let __lane242_0 = __lanes.lanes(__lane242)[0];
        let __lane251_0 = __lanes.lanes(__lane251)[0];
        let __lane260_0 = __lanes.lanes(__lane260)[0];
        let __lane265_0 = __lanes.lanes(__lane265)[0];
        let __lane270_0 = __lanes.lanes(__lane270)[0];
        let __lane275_0 = __lanes.lanes(__lane275)[0];
        let __lane280_0 = __lanes.lanes(__lane280)[0];
        let __lane285_0 = __lanes.lanes(__lane285)[0];
        let __lane76_1 = __lanes.lanes(__lane76)[1];
        let __lane83_1 = __lanes.lanes(__lane83)[1];
        let __lane88_1 = __lanes.lanes(__lane88)[1];
        let __lane93_1 = __lanes.lanes(__lane93)[1];
        let __lane98_1 = __lanes.lanes(__lane98)[1];
        let __lane103_1 = __lanes.lanes(__lane103)[1];
        let __lane108_1 = __lanes.lanes(__lane108)[1];
        let __lane117_1 = __lanes.lanes(__lane117)[1];
        let __lane122_1 = __lanes.lanes(__lane122)[1];
        let __lane127_1 = __lanes.lanes(__lane127)[1];
        let __lane132_1 = __lanes.lanes(__lane132)[1];
        let __lane137_1 = __lanes.lanes(__lane137)[1];
        let __lane142_1 = __lanes.lanes(__lane142)[1];
        let __lane151_1 = __lanes.lanes(__lane151)[1];
        let __lane160_1 = __lanes.lanes(__lane160)[1];
        let __lane165_1 = __lanes.lanes(__lane165)[1];
        let __lane170_1 = __lanes.lanes(__lane170)[1];
        let __lane175_1 = __lanes.lanes(__lane175)[1];
        let __lane180_1 = __lanes.lanes(__lane180)[1];
        let __lane185_1 = __lanes.lanes(__lane185)[1];
        let __lane194_1 = __lanes.lanes(__lane194)[1];
        let __lane203_1 = __lanes.lanes(__lane203)[1];
        let __lane212_1 = __lanes.lanes(__lane212)[1];
        let __lane217_1 = __lanes.lanes(__lane217)[1];
        let __lane222_1 = __lanes.lanes(__lane222)[1];
        let __lane227_1 = __lanes.lanes(__lane227)[1];
        let __lane232_1 = __lanes.lanes(__lane232)[1];
        let __lane237_1 = __lanes.lanes(__lane237)[1];
        let __lane242_1 = __lanes.lanes(__lane242)[1];
        let __lane251_1 = __lanes.lanes(__lane251)[1];
        let __lane260_1 = __lanes.lanes(__lane260)[1];
        let __lane265_1 = __lanes.lanes(__lane265)[1];
        let __lane270_1 = __lanes.lanes(__lane270)[1];
        let __lane275_1 = __lanes.lanes(__lane275)[1];
        let __lane280_1 = __lanes.lanes(__lane280)[1];
        let __lane285_1 = __lanes.lanes(__lane285)[1];
        let __lane76_2 = __lanes.lanes(__lane76)[2];
        let __lane83_2 = __lanes.lanes(__lane83)[2];
        let __lane88_2 = __lanes.lanes(__lane88)[2];
        let __lane93_2 = __lanes.lanes(__lane93)[2];
        let __lane98_2 = __lanes.lanes(__lane98)[2];
        let __lane103_2 = __lanes.lanes(__lane103)[2];
        let __lane108_2 = __lanes.lanes(__lane108)[2];
        let __lane117_2 = __lanes.lanes(__lane117)[2];
        let __lane122_2 = __lanes.lanes(__lane122)[2];
        let __lane127_2 = __lanes.lanes(__lane127)[2];
        let __lane132_2 = __lanes.lanes(__lane132)[2];
        let __lane137_2 = __lanes.lanes(__lane137)[2];
        let __lane142_2 = __lanes.lanes(__lane142)[2];
        let __lane151_2 = __lanes.lanes(__lane151)[2];
        let __lane160_2 = __lanes.lanes(__lane160)[2];
        let __lane165_2 = __lanes.lanes(__lane165)[2];
        let __lane170_2 = __lanes.lanes(__lane170)[2];
        let __lane175_2 = __lanes.lanes(__lane175)[2];
        let __lane180_2 = __lanes.lanes(__lane180)[2];
        let __lane185_2 = __lanes.lanes(__lane185)[2];
        let __lane194_2 = __lanes.lanes(__lane194)[2];
        let __lane203_2 = __lanes.lanes(__lane203)[2];
        let __lane212_2 = __lanes.lanes(__lane212)[2];
        let __lane217_2 = __lanes.lanes(__lane217)[2];
        let __lane222_2 = __lanes.lanes(__lane222)[2];
        let __lane227_2 = __lanes.lanes(__lane227)[2];
        let __lane232_2 = __lanes.lanes(__lane232)[2];
        let __lane237_2 = __lanes.lanes(__lane237)[2];
        let __lane242_2 = __lanes.lanes(__lane242)[2];
        let __lane251_2 = __lanes.lanes(__lane251)[2];
        let __lane260_2 = __lanes.lanes(__lane260)[2];
        let __lane265_2 = __lanes.lanes(__lane265)[2];
        let __lane270_2 = __lanes.lanes(__lane270)[2];
        let __lane275_2 = __lanes.lanes(__lane275)[2];
        let __lane280_2 = __lanes.lanes(__lane280)[2];
        let __lane285_2 = __lanes.lanes(__lane285)[2];
        let __lane76_3 = __lanes.lanes(__lane76)[3];
        let __lane83_3 = __lanes.lanes(__lane83)[3];
        let __lane88_3 = __lanes.lanes(__lane88)[3];
        let __lane93_3 = __lanes.lanes(__lane93)[3];
        let __lane98_3 = __lanes.lanes(__lane98)[3];
        let __lane103_3 = __lanes.lanes(__lane103)[3];
        let __lane108_3 = __lanes.lanes(__lane108)[3];
        let __lane117_3 = __lanes.lanes(__lane117)[3];
        let __lane122_3 = __lanes.lanes(__lane122)[3];
        let __lane127_3 = __lanes.lanes(__lane127)[3];
        let __lane132_3 = __lanes.lanes(__lane132)[3];
        let __lane137_3 = __lanes.lanes(__lane137)[3];
        let __lane142_3 = __lanes.lanes(__lane142)[3];
        let __lane151_3 = __lanes.lanes(__lane151)[3];
        let __lane160_3 = __lanes.lanes(__lane160)[3];
        let __lane165_3 = __lanes.lanes(__lane165)[3];
        let __lane170_3 = __lanes.lanes(__lane170)[3];
        let __lane175_3 = __lanes.lanes(__lane175)[3];
        let __lane180_3 = __lanes.lanes(__lane180)[3];
        let __lane185_3 = __lanes.lanes(__lane185)[3];
        let __lane194_3 = __lanes.lanes(__lane194)[3];
        let __lane203_3 = __lanes.lanes(__lane203)[3];
        let __lane212_3 = __lanes.lanes(__lane212)[3];
        let __lane217_3 = __lanes.lanes(__lane217)[3];
        let __lane222_3 = __lanes.lanes(__lane222)[3];
        let __lane227_3 = __lanes.lanes(__lane227)[3];
        let __lane232_3 = __lanes.lanes(__lane232)[3];
        let __lane237_3 = __lanes.lanes(__lane237)[3];
        let __lane242_3 = __lanes.lanes(__lane242)[3];
        let __lane251_3 = __lanes.lanes(__lane251)[3];
        let __lane260_3 = __lanes.lanes(__lane260)[3];
        let __lane265_3 = __lanes.lanes(__lane265)[3];
        let __lane270_3 = __lanes.lanes(__lane270)[3];
        let __lane275_3 = __lanes.lanes(__lane275)[3];
        let __lane280_3 = __lanes.lanes(__lane280)[3];
        let __lane285_3 = __lanes.lanes(__lane285)[3];
        let __lane_zero = 0.0_f64;
        let __lane289_0 = __lanes.lanes(__lane289)[0];
        let __lane290_0 = __lanes.lanes(__lane290)[0];
        let __lane291_0 = __lanes.lanes(__lane291)[0];
        let __lane292_0 = __lanes.lanes(__lane292)[0];
        let __lane293_0 = __lanes.lanes(__lane293)[0];
        let __lane294_0 = __lanes.lanes(__lane294)[0];
        let __lane295_0 = __lanes.lanes(__lane295)[0];
        let __lane296_0 = __lanes.lanes(__lane296)[0];
        let __lane299_0 = __lanes.lanes(__lane299)[0];
        let __lane302_0 = __lanes.lanes(__lane302)[0];
        let __lane307_0 = __lanes.lanes(__lane307)[0];
        let __lane312_0 = __lanes.lanes(__lane312)[0];
        let __lane317_0 = __lanes.lanes(__lane317)[0];
        let __lane322_0 = __lanes.lanes(__lane322)[0];
        let __lane327_0 = __lanes.lanes(__lane327)[0];
        let __lane289_1 = __lanes.lanes(__lane289)[1];
        let __lane290_1 = __lanes.lanes(__lane290)[1];
        let __lane291_1 = __lanes.lanes(__lane291)[1];
        let __lane292_1 = __lanes.lanes(__lane292)[1];
        let __lane293_1 = __lanes.lanes(__lane293)[1];
        let __lane294_1 = __lanes.lanes(__lane294)[1];
        let __lane295_1 = __lanes.lanes(__lane295)[1];
        let __lane296_1 = __lanes.lanes(__lane296)[1];
        let __lane299_1 = __lanes.lanes(__lane299)[1];
        let __lane302_1 = __lanes.lanes(__lane302)[1];
        let __lane307_1 = __lanes.lanes(__lane307)[1];
        let __lane312_1 = __lanes.lanes(__lane312)[1];
        let __lane317_1 = __lanes.lanes(__lane317)[1];
        let __lane322_1 = __lanes.lanes(__lane322)[1];
        let __lane327_1 = __lanes.lanes(__lane327)[1];
        ::planar_arm::__private::columns([
            [__lane76_0, __lane76_1, __lane76_2, __lane76_3, __lane_zero, __lane_zero],
            [__lane83_0, __lane83_1, __lane83_2, __lane83_3, __lane_zero, __lane_zero],
            [__lane88_0, __lane88_1, __lane88_2, __lane88_3, __lane_zero, __lane_zero],
            [__lane93_0, __lane93_1, __lane93_2, __lane93_3, __lane_zero, __lane_zero],
            [__lane98_0, __lane98_1, __lane98_2, __lane98_3, __lane_zero, __lane_zero],
            [
                __lane103_0,
                __lane103_1,
                __lane103_2,
                __lane103_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane108_0,
                __lane108_1,
                __lane108_2,
                __lane108_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane117_0,
                __lane117_1,
                __lane117_2,
                __lane117_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane122_0,
                __lane122_1,
                __lane122_2,
                __lane122_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane127_0,
                __lane127_1,
                __lane127_2,
                __lane127_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane132_0,
                __lane132_1,
                __lane132_2,
                __lane132_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane137_0,
                __lane137_1,
                __lane137_2,
                __lane137_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane142_0,
                __lane142_1,
                __lane142_2,
                __lane142_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane151_0,
                __lane151_1,
                __lane151_2,
                __lane151_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane160_0,
                __lane160_1,
                __lane160_2,
                __lane160_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane165_0,
                __lane165_1,
                __lane165_2,
                __lane165_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane170_0,
                __lane170_1,
                __lane170_2,
                __lane170_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane175_0,
                __lane175_1,
                __lane175_2,
                __lane175_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane180_0,
                __lane180_1,
                __lane180_2,
                __lane180_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane185_0,
                __lane185_1,
                __lane185_2,
                __lane185_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane194_0,
                __lane194_1,
                __lane194_2,
                __lane194_3,
                __lane289_0,
                __lane289_1,
            ],
            [
                __lane203_0,
                __lane203_1,
                __lane203_2,
                __lane203_3,
                __lane_zero,
                __lane_zero,
            ],
            [
                __lane212_0,
                __lane212_1,
                __lane212_2,
                __lane212_3,
                __lane290_0,
                __lane290_1,
            ],
            [
                __lane217_0,
                __lane217_1,
                __lane217_2,
                __lane217_3,
                __lane291_0,
                __lane291_1,
            ],
            [
                __lane222_0,
                __lane222_1,
                __lane222_2,
                __lane222_3,
                __lane292_0,
                __lane292_1,
            ],
            [
                __lane227_0,
                __lane227_1,
                __lane227_2,
                __lane227_3,
                __lane293_0,
                __lane293_1,
            ],
            [
                __lane232_0,
                __lane232_1,
                __lane232_2,
                __lane232_3,
                __lane294_0,
                __lane294_1,
            ],
            [
                __lane237_0,
                __lane237_1,
                __lane237_2,
                __lane237_3,
                __lane295_0,
                __lane295_1,
            ],
            [
                __lane242_0,
                __lane242_1,
                __lane242_2,
                __lane242_3,
                __lane296_0,
                __lane296_1,
            ],
            [
                __lane251_0,
                __lane251_1,
                __lane251_2,
                __lane251_3,
                __lane299_0,
                __lane299_1,
            ],
            [
                __lane260_0,
                __lane260_1,
                __lane260_2,
                __lane260_3,
                __lane302_0,
                __lane302_1,
            ],
            [
                __lane265_0,
                __lane265_1,
                __lane265_2,
                __lane265_3,
                __lane307_0,
                __lane307_1,
            ],
            [
                __lane270_0,
                __lane270_1,
                __lane270_2,
                __lane270_3,
                __lane312_0,
                __lane312_1,
            ],
            [
                __lane275_0,
                __lane275_1,
                __lane275_2,
                __lane275_3,
                __lane317_0,
                __lane317_1,
            ],
            [
                __lane280_0,
                __lane280_1,
                __lane280_2,
                __lane280_3,
                __lane322_0,
                __lane322_1,
            ],
            [
                __lane285_0,
                __lane285_1,
                __lane285_2,
                __lane285_3,
                __lane327_0,
                __lane327_1,
            ],
        ])
    }
    /**The arm's base parameters now. The base parameters, each an exact combination of the standard ones, found at compile time by rational elimination on the regressor evaluated exactly at rational points:

1. `mx2 + 2159/5000 m2 + 2159/5000 m3 + 2159/5000 m4 + 2159/5000 m5 + 2159/5000 m6`
2. `my2`
3. `xx2 - yy2 + 4661281/25000000 m2 + 4661281/25000000 m3 + 4661281/25000000 m4 + 4661281/25000000 m5 + 4661281/25000000 m6`
4. `xy2`
5. `xz2 + 2159/5000 my3 - 2159/5000 mz2 - 6479159/100000000 m3 - 6479159/100000000 m4 - 6479159/100000000 m5 - 6479159/100000000 m6`
6. `yz2`
7. `zz2 - 4661281/25000000 m2 - 4661281/25000000 m3 - 4661281/25000000 m4 - 4661281/25000000 m5 - 4661281/25000000 m6`
8. `mx3 + 203/10000 m3 + 203/10000 m4 + 203/10000 m5 + 203/10000 m6`
9. `xx3 - 3001/10000 my3 + yy1 + yy2 - 4661281/25000000 m2 - yy3 - 65409659/400000000 m3 - 65409659/400000000 m4 - 65409659/400000000 m5 - 65409659/400000000 m6`
10. `xy3 - 203/10000 my3`
11. `xz3`
12. `yz3`
13. `zz3 - 3001/10000 my3 + yy1 + yy2 - 4661281/25000000 m2 - 65739331/400000000 m3 - 65739331/400000000 m4 - 65739331/400000000 m5 - 65739331/400000000 m6`
14. `mx4`
15. `my4 + mz3 + 2159/5000 m4 + 2159/5000 m5 + 2159/5000 m6`
16. `xx4 + yy3 - 2159/2500 mz3 - 41209/100000000 m3 - yy4 - 18686333/100000000 m4 - 18686333/100000000 m5 - 18686333/100000000 m6`
17. `xy4`
18. `xz4`
19. `yz4`
20. `zz4 + yy3 - 2159/2500 mz3 - 41209/100000000 m3 - 18686333/100000000 m4 - 18686333/100000000 m5 - 18686333/100000000 m6`
21. `mx5`
22. `my5 - mz4`
23. `mz5 + mz6`
24. `xx5 + yy4 + yy6`
25. `xy5`
26. `yy5 + yy6`
27. `xz5`
28. `yz5`
29. `zz5 + yy4`
30. `mx6`
31. `my6`
32. `xx6 - yy6`
33. `xy6`
34. `xz6`
35. `yz6`
36. `zz6`


Cost: 0 multiplications, 0 additions, 0 divisions, 0 sin_cos pairs.*/
    #[inline]
    fn base_parameters(
        &self,
    ) -> ::planar_arm::nalgebra::SVector<::core::primitive::f64, 36> {
        let __b1 = (379559.0 / 100000.0);
        let __b2 = (261.0 / 2500.0);
        let __b3 = (1035005161.0 / 500000000.0);
        let __b4 = (474759.0 / 12500000.0);
        let __b5 = (-(1380782687.0 / 2000000000.0));
        let __b6 = (-(23751.0 / 1000000.0));
        let __b7 = (-(1034378761.0 / 500000000.0));
        let __b8 = (203.0 / 8000.0);
        let __b9 = (-(8086633907.0 / 8000000000.0));
        let __b10 = 0.0;
        let __b11 = (4263.0 / 625000.0);
        let __b12 = (2961.0 / 625000.0);
        let __b13 = (-(8094875707.0 / 8000000000.0));
        let __b15 = (89133.0 / 100000.0);
        let __b16 = (-(199973097.0 / 400000000.0));
        let __b23 = (9.0 / 3125.0);
        let __b24 = (36.0 / 390625.0);
        ::planar_arm::__private::vector([
            __b1,
            __b2,
            __b3,
            __b4,
            __b5,
            __b6,
            __b7,
            __b8,
            __b9,
            __b10,
            __b11,
            __b12,
            __b13,
            __b10,
            __b15,
            __b16,
            __b10,
            __b10,
            __b10,
            __b16,
            __b10,
            __b10,
            __b23,
            __b24,
            __b10,
            __b24,
            __b10,
            __b10,
            __b10,
            __b10,
            __b10,
            __b10,
            __b10,
            __b10,
            __b10,
            __b10,
        ])
    }
}
