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
        ::planar_arm::__private::matrix([
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
        ::planar_arm::__private::matrix([
            [__c11, __c12, __c13, __c14, __c15, __c16],
            [__c21, __c22, __c23, __c24, __c25, __c26],
            [__c31, __c32, __c33, __c34, __c35, __c26],
            [__c41, __c42, __c43, __c44, __c45, __c46],
            [__c51, __c52, __c53, __c54, __c55, __c56],
            [__c61, __c62, __c62, __c64, __c65, __c66],
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
            ::planar_arm::__private::matrix([
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

the unrolled recursive Newton-Euler algorithm differentiated at compile time, operation by operation

Cost: 1456 multiplications, 1164 additions, 0 divisions, 5 sin_cos pairs.*/
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
            ::planar_arm::__private::matrix([
                [
                    __dtau1_dq1,
                    __dtau1_dq2,
                    __dtau1_dq3,
                    __dtau1_dq4,
                    __dtau1_dq5,
                    __dtau1_dq6,
                ],
                [
                    __dtau1_dq1,
                    __dtau2_dq2,
                    __dtau2_dq3,
                    __dtau2_dq4,
                    __dtau2_dq5,
                    __dtau2_dq6,
                ],
                [
                    __dtau1_dq1,
                    __dtau3_dq2,
                    __dtau3_dq3,
                    __dtau3_dq4,
                    __dtau3_dq5,
                    __dtau3_dq6,
                ],
                [
                    __dtau1_dq1,
                    __dtau4_dq2,
                    __dtau4_dq3,
                    __dtau4_dq4,
                    __dtau4_dq5,
                    __dtau4_dq6,
                ],
                [
                    __dtau1_dq1,
                    __dtau5_dq2,
                    __dtau5_dq3,
                    __dtau5_dq4,
                    __dtau5_dq5,
                    __dtau5_dq6,
                ],
                [
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                ],
            ]),
            ::planar_arm::__private::matrix([
                [
                    __dtau1_dqd1,
                    __dtau1_dqd2,
                    __dtau1_dqd3,
                    __dtau1_dqd4,
                    __dtau1_dqd5,
                    __dtau1_dqd6,
                ],
                [
                    __dtau2_dqd1,
                    __dtau2_dqd2,
                    __dtau2_dqd3,
                    __dtau2_dqd4,
                    __dtau2_dqd5,
                    __dtau2_dqd6,
                ],
                [
                    __dtau3_dqd1,
                    __dtau3_dqd2,
                    __dtau3_dqd3,
                    __dtau3_dqd4,
                    __dtau3_dqd5,
                    __dtau3_dqd6,
                ],
                [
                    __dtau4_dqd1,
                    __dtau4_dqd2,
                    __dtau4_dqd3,
                    __dtau4_dqd4,
                    __dtau4_dqd5,
                    __dtau4_dqd6,
                ],
                [
                    __dtau5_dqd1,
                    __dtau5_dqd2,
                    __dtau5_dqd3,
                    __dtau5_dqd4,
                    __dtau5_dqd5,
                    __dtau5_dqd6,
                ],
                [
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
                    __dtau1_dq1,
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
    /// The kinetic energy qd^T M qd / 2, J, armature included.
    #[inline]
    fn kinetic_energy<__T: ::planar_arm::Real>(
        &self,
        __q: &::planar_arm::nalgebra::SVector<__T, 6>,
        __qd: &::planar_arm::nalgebra::SVector<__T, 6>,
    ) -> __T {
        ::planar_arm::__private::kinetic_energy(&self.mass_matrix(__q), __qd)
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
        ::planar_arm::__private::matrix([
            [__j11, __j12, __j13, __j14, __j15, __j15],
            [__j21, __j22, __j23, __j24, __j15, __j15],
            [__j15, __j32, __j33, __j34, __j15, __j15],
            [__j15, __s1, __s1, __j44, __j45, __j46],
            [__j15, __j52, __j52, __j54, __j55, __j56],
            [__j61, __j15, __j15, __j64, __j65, __j66],
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
        ::planar_arm::__private::matrix([
            [
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __qdd1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_11,
                __y1_12,
                __y1_13,
                __y1_14,
                __y1_15,
                __y1_16,
                __y1_17,
                __y1_18,
                __y1_19,
                __y1_20,
                __y1_21,
                __y1_22,
                __y1_23,
                __y1_24,
                __y1_25,
                __y1_26,
                __y1_27,
                __y1_28,
                __y1_29,
                __y1_30,
                __y1_31,
                __y1_32,
                __y1_33,
                __y1_34,
                __y1_35,
                __y1_36,
                __y1_37,
                __y1_38,
                __y1_39,
                __y1_40,
                __y1_41,
                __y1_42,
                __y1_43,
                __y1_44,
                __y1_45,
                __y1_46,
                __y1_47,
                __y1_48,
                __y1_49,
                __y1_50,
                __y1_51,
                __y1_52,
                __y1_53,
                __y1_54,
                __y1_55,
                __y1_56,
                __y1_57,
                __y1_58,
                __y1_59,
                __y1_60,
            ],
            [
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y2_11,
                __y2_12,
                __y2_13,
                __y2_14,
                __y2_15,
                __y2_16,
                __y2_17,
                __y2_18,
                __y2_19,
                __qdd2,
                __y2_21,
                __y2_22,
                __y2_23,
                __y2_24,
                __y2_25,
                __y2_26,
                __y2_27,
                __y2_28,
                __y2_29,
                __y2_30,
                __y2_31,
                __y2_32,
                __y2_33,
                __y2_34,
                __y2_35,
                __y2_36,
                __y2_37,
                __y2_38,
                __y2_39,
                __y2_40,
                __y2_41,
                __y2_42,
                __y2_43,
                __y2_44,
                __y2_45,
                __y2_46,
                __y2_47,
                __y2_48,
                __y2_49,
                __y2_50,
                __y2_51,
                __y2_52,
                __y2_53,
                __y2_54,
                __y2_55,
                __y2_56,
                __y2_57,
                __y2_58,
                __y2_59,
                __y2_60,
            ],
            [
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y3_21,
                __y3_22,
                __y3_23,
                __y3_24,
                __y2_25,
                __y2_26,
                __y2_27,
                __y2_28,
                __y2_29,
                __y2_30,
                __y3_31,
                __y3_32,
                __y3_33,
                __y3_34,
                __y2_35,
                __y2_36,
                __y2_37,
                __y2_38,
                __y2_39,
                __y2_40,
                __y3_41,
                __y3_42,
                __y3_43,
                __y3_44,
                __y2_45,
                __y2_46,
                __y2_47,
                __y2_48,
                __y2_49,
                __y2_50,
                __y3_51,
                __y3_52,
                __y3_53,
                __y3_54,
                __y2_55,
                __y2_56,
                __y2_57,
                __y2_58,
                __y2_59,
                __y2_60,
            ],
            [
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y4_32,
                __y1_1,
                __y4_34,
                __y4_35,
                __y4_36,
                __y4_37,
                __y4_38,
                __y4_39,
                __y4_40,
                __y1_1,
                __y4_42,
                __y4_43,
                __y4_44,
                __y4_45,
                __y4_46,
                __y4_47,
                __y4_48,
                __y4_49,
                __y4_50,
                __y1_1,
                __y4_52,
                __y4_53,
                __y4_54,
                __y4_55,
                __y4_56,
                __y4_57,
                __y4_58,
                __y4_59,
                __y4_60,
            ],
            [
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y5_42,
                __y1_1,
                __y5_44,
                __y5_45,
                __y5_46,
                __y5_47,
                __y5_48,
                __y5_49,
                __y5_50,
                __y1_1,
                __y5_52,
                __y5_53,
                __y5_54,
                __y5_55,
                __y5_56,
                __y5_57,
                __y5_58,
                __y5_59,
                __y5_60,
            ],
            [
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y1_1,
                __y6_52,
                __y6_53,
                __y1_1,
                __y6_55,
                __y6_56,
                __y6_57,
                __y6_58,
                __y6_59,
                __y6_60,
            ],
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

Cost: 464 multiplications, 398 additions, 0 divisions, 5 sin_cos pairs.*/
    #[inline]
    fn base_regressor(
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
        ::planar_arm::__private::matrix([
            [
                __y1_1,
                __y1_2,
                __y1_3,
                __y1_4,
                __y1_5,
                __y1_6,
                __y1_7,
                __y1_8,
                __y1_9,
                __y1_10,
                __y1_11,
                __y1_12,
                __y1_13,
                __y1_14,
                __y1_15,
                __y1_16,
                __y1_17,
                __y1_18,
                __y1_19,
                __y1_20,
                __y1_21,
                __y1_22,
                __y1_23,
                __y1_24,
                __y1_25,
                __y1_26,
                __y1_27,
                __y1_28,
                __y1_29,
                __y1_30,
                __y1_31,
                __y1_32,
                __y1_33,
                __y1_34,
                __y1_35,
                __y1_36,
            ],
            [
                __y2_1,
                __y2_2,
                __y2_3,
                __y2_4,
                __y2_5,
                __y2_6,
                __qdd2,
                __y2_8,
                __y2_9,
                __y2_10,
                __y2_11,
                __y2_12,
                __y2_13,
                __y2_14,
                __y2_15,
                __y2_16,
                __y2_17,
                __y2_18,
                __y2_19,
                __y2_20,
                __y2_21,
                __y2_22,
                __y2_23,
                __y2_24,
                __y2_25,
                __y2_26,
                __y2_27,
                __y2_28,
                __y2_29,
                __y2_30,
                __y2_31,
                __y2_32,
                __y2_33,
                __y2_34,
                __y2_35,
                __y2_36,
            ],
            [
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_8,
                __y2_9,
                __y2_10,
                __y2_11,
                __y2_12,
                __y2_13,
                __y3_14,
                __y3_15,
                __y2_16,
                __y2_17,
                __y2_18,
                __y2_19,
                __y2_20,
                __y3_21,
                __y3_22,
                __y3_23,
                __y2_24,
                __y2_25,
                __y2_26,
                __y2_27,
                __y2_28,
                __y2_29,
                __y3_30,
                __y3_31,
                __y2_32,
                __y2_33,
                __y2_34,
                __y2_35,
                __y2_36,
            ],
            [
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y4_14,
                __y3_1,
                __y4_16,
                __y4_17,
                __y4_18,
                __y4_19,
                __y4_20,
                __y4_21,
                __y4_22,
                __y4_23,
                __y4_24,
                __y4_25,
                __y4_26,
                __y4_27,
                __y4_28,
                __y4_29,
                __y4_30,
                __y4_31,
                __y4_32,
                __y4_33,
                __y4_34,
                __y4_35,
                __y4_36,
            ],
            [
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y5_21,
                __y3_1,
                __y5_23,
                __y5_24,
                __y5_25,
                __y5_26,
                __y5_27,
                __y5_28,
                __y5_29,
                __y5_30,
                __y5_31,
                __y5_32,
                __y5_33,
                __y5_34,
                __y5_35,
                __y5_36,
            ],
            [
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y3_1,
                __y6_30,
                __y6_31,
                __y6_32,
                __y6_33,
                __y6_34,
                __y6_35,
                __y6_36,
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
