#[automatically_derived]
#[allow(clippy::nursery)]
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
        let __t14 = __T::from_f64(91.0 / 400.0) * __t6
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t15 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t5;
        let __t16 = __T::from_f64(3.0 / 500.0) * __t5
            - __T::from_f64(-(1819.0 / 5000.0)) * __t6;
        let __t17 = __T::from_f64(87.0 / 5.0)
            * (__t12 + __t6 * __t16 - __qd2 * __t15 + __T::from_f64(91.0 / 400.0) * __t8
                - __T::from_f64(3.0 / 500.0) * __qdd2);
        let __t18 = __T::from_f64(87.0 / 5.0)
            * (__t13 + __qd2 * __t14 - __t5 * __t16
                + __T::from_f64(-(1819.0 / 5000.0)) * __qdd2
                - __T::from_f64(91.0 / 400.0) * __t7);
        let __t19 = __T::from_f64(87.0 / 5.0)
            * (__t11 + __t5 * __t15 - __t6 * __t14 + __T::from_f64(3.0 / 500.0) * __t7
                - __T::from_f64(-(1819.0 / 5000.0)) * __t8);
        let __t20 = __c3 * __t5 + __s3 * __t6;
        let __t21 = __t1 * __t5 + __c3 * __t6;
        let __t22 = -__qd3;
        let __t23 = -__qd2 - __qd3;
        let __t24 = -__qdd2 - __qdd3;
        let __t25 = __c3 * __t7 + __s3 * __t8 - __t21 * __t22;
        let __t26 = __t1 * __t7 + __c3 * __t8 + __t20 * __t22;
        let __t27 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t21);
        let __t28 = __T::from_f64(203.0 / 10000.0) * __t21;
        let __t29 = __T::from_f64(-(3001.0 / 20000.0)) * __t20
            - __T::from_f64(203.0 / 10000.0) * __t23;
        let __t30 = __c3 * __t12 + __s3 * __t13 + __t23 * __t29 - __t21 * __t28
            - __T::from_f64(-(3001.0 / 20000.0)) * __t26;
        let __t31 = __t21 * __t27 - __t20 * __t29
            + __T::from_f64(203.0 / 10000.0) * __t26 - __t11;
        let __t32 = __t1 * __t12 + __c3 * __t13 + __t20 * __t28 - __t23 * __t27
            + __T::from_f64(-(3001.0 / 20000.0)) * __t25
            - __T::from_f64(203.0 / 10000.0) * __t24;
        let __t33 = __T::from_f64(7.0 / 100.0) * __t23
            - __T::from_f64(-(141.0 / 10000.0)) * __t21;
        let __t34 = __T::from_f64(-(203.0 / 10000.0)) * __t21
            - __T::from_f64(7.0 / 100.0) * __t20;
        let __t35 = __T::from_f64(-(141.0 / 10000.0)) * __t20
            - __T::from_f64(-(203.0 / 10000.0)) * __t23;
        let __t36 = __T::from_f64(24.0 / 5.0)
            * (__t30 + __t23 * __t35 - __t21 * __t34 + __T::from_f64(7.0 / 100.0) * __t24
                - __T::from_f64(-(141.0 / 10000.0)) * __t26);
        let __t37 = __T::from_f64(24.0 / 5.0)
            * (__t31 + __t21 * __t33 - __t20 * __t35
                + __T::from_f64(-(203.0 / 10000.0)) * __t26
                - __T::from_f64(7.0 / 100.0) * __t25);
        let __t38 = __T::from_f64(24.0 / 5.0)
            * (__t32 + __t20 * __t34 - __t23 * __t33
                + __T::from_f64(-(141.0 / 10000.0)) * __t25
                - __T::from_f64(-(203.0 / 10000.0)) * __t24);
        let __t39 = __c4 * __t20 + __s4 * __t23;
        let __t40 = __t2 * __t20 + __c4 * __t23;
        let __t41 = -__t40;
        let __t42 = __t21 + __qd4;
        let __t43 = __c4 * __t25 + __s4 * __t24 - __qd4 * __t41;
        let __t44 = __qd4 * __t39 - (__t2 * __t25 + __c4 * __t24);
        let __t45 = -(__T::from_f64(2159.0 / 5000.0) * __t41);
        let __t46 = __T::from_f64(2159.0 / 5000.0) * __t39;
        let __t47 = __c4 * __t30 + __s4 * __t31 + __t42 * __t46
            - __T::from_f64(2159.0 / 5000.0) * __t44;
        let __t48 = __t32 + __t41 * __t45 - __t39 * __t46;
        let __t49 = __T::from_f64(2159.0 / 5000.0) * __t43 - __t42 * __t45
            - (__t2 * __t30 + __c4 * __t31);
        let __t50 = -(__T::from_f64(19.0 / 1000.0) * __t41);
        let __t51 = __T::from_f64(19.0 / 1000.0) * __t39;
        let __t52 = __T::from_f64(41.0 / 50.0)
            * (__t47 + __t42 * __t51 - __T::from_f64(19.0 / 1000.0) * __t44);
        let __t53 = __T::from_f64(41.0 / 50.0)
            * (__t49 + __T::from_f64(19.0 / 1000.0) * __t43 - __t42 * __t50);
        let __t54 = __c5 * __t47 + __s5 * __t48;
        let __t55 = __t3 * __t47 + __c5 * __t48;
        let __t56 = -__t49;
        let __t57 = __c5 * __t39 + __s5 * __t42;
        let __t58 = __t3 * __t39 + __c5 * __t42;
        let __t59 = __t40 - __qd5;
        let __t60 = -__t44 - __qdd5;
        let __t61 = __c5 * __t43 + __s5 * (__t26 + __qdd4) - __t58 * (-__qd5);
        let __t62 = __c6 * __t57 + __s6 * __t59;
        let __t63 = __t4 * __t57 + __c6 * __t59;
        let __t64 = __t58 + __qd6;
        let __t65 = __T::from_f64(4.0 / 125.0) * __t63;
        let __t66 = -(__T::from_f64(4.0 / 125.0) * __t62);
        let __t67 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t54 + __s6 * __t56
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t61 + __c6 * __t60 - __qd6 * __t62) - __t64 * __t66);
        let __t68 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t54 + __c6 * __t56 + __t64 * __t65
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t61 + __s6 * __t60 + __qd6 * __t63));
        let __t69 = -(__T::from_f64(4.0 / 125.0) * __t68);
        let __t70 = __T::from_f64(4.0 / 125.0) * __t67;
        let __t71 = __c6 * __t69 + __t4 * __t70;
        let __t72 = __s6 * __t69 + __c6 * __t70;
        let __t73 = __T::from_f64(17.0 / 50.0) * __t54 + __c6 * __t67 + __t4 * __t68;
        let __t74 = __T::from_f64(17.0 / 50.0) * __t55
            + __T::from_f64(9.0 / 100.0) * (__t55 + __t62 * __t66 - __t63 * __t65);
        let __t5_2 = -__t72;
        let __t4_2 = __s5 * __t71;
        let __t75 = __t52 + __c5 * __t73 + __t3 * __t74;
        let __t76 = __t53
            - (__T::from_f64(17.0 / 50.0) * __t56 + __s6 * __t67 + __c6 * __t68);
        let __t77 = __T::from_f64(19.0 / 1000.0) * __t53 + __c5 * __t71
            + __T::from_f64(2159.0 / 5000.0) * __t76;
        let __t78 = -__t76;
        let __t79 = -(-(__T::from_f64(19.0 / 1000.0) * __t52) - __t72
            - __T::from_f64(2159.0 / 5000.0) * __t75);
        let __t80 = __t36 + __c4 * __t75 + __t2 * __t78;
        let __t81 = __t37 + __s4 * __t75 + __c4 * __t78;
        let __t82 = __t38
            + __T::from_f64(41.0 / 50.0) * (__t48 + __t41 * __t50 - __t39 * __t51)
            + __s5 * __t73 + __c5 * __t74;
        let __t83 = __T::from_f64(-(141.0 / 10000.0)) * __t38
            - __T::from_f64(7.0 / 100.0) * __t37 + __c4 * __t77 + __t2 * __t79
            + __T::from_f64(-(3001.0 / 20000.0)) * __t82;
        let __t84 = __T::from_f64(7.0 / 100.0) * __t36
            - __T::from_f64(-(203.0 / 10000.0)) * __t38 + __s4 * __t77 + __c4 * __t79
            - __T::from_f64(203.0 / 10000.0) * __t82;
        let __t85 = __T::from_f64(-(203.0 / 10000.0)) * __t37
            - __T::from_f64(-(141.0 / 10000.0)) * __t36 + __t4_2
            + __T::from_f64(203.0 / 10000.0) * __t81
            - __T::from_f64(-(3001.0 / 20000.0)) * __t80;
        let __t3_2 = -__t84;
        let __t2_2 = __T::from_f64(-(1819.0 / 5000.0)) * __t18
            - __T::from_f64(3.0 / 500.0) * __t17 - __t84
            + __T::from_f64(2159.0 / 5000.0) * (__t18 + __s3 * __t80 + __c3 * __t82);
        let __t1_2 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t19 - __T::from_f64(91.0 / 400.0) * __t18
                + __c3 * __t83 + __t1 * __t85)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t17
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t19 + __s3 * __t83
                    + __c3 * __t85 - __T::from_f64(2159.0 / 5000.0) * (__t19 - __t81));
        let __t6_2 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__t1_2, __t2_2, __t3_2, __t4_2, __t5_2, __t6_2])
    }
    /**The mass matrix M(q), each joint's armature on its diagonal.

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
        let __t15 = __T::from_f64(91.0 / 400.0) * __t6
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t16 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t5;
        let __t17 = __T::from_f64(3.0 / 500.0) * __t5
            - __T::from_f64(-(1819.0 / 5000.0)) * __t6;
        let __t18 = __T::from_f64(87.0 / 5.0)
            * (__t11 + __t6 * __t17 - __qd2 * __t16
                + __T::from_f64(91.0 / 400.0) * __t8);
        let __t19 = __T::from_f64(87.0 / 5.0)
            * (__qd2 * __t15 - __t5 * __t17 - __T::from_f64(91.0 / 400.0) * __t7
                - __t12);
        let __t20 = __T::from_f64(87.0 / 5.0)
            * (__t14 + __t5 * __t16 - __t6 * __t15 + __T::from_f64(3.0 / 500.0) * __t7
                - __T::from_f64(-(1819.0 / 5000.0)) * __t8);
        let __t21 = __c3 * __t5 + __s3 * __t6;
        let __t22 = __t1 * __t5 + __c3 * __t6;
        let __t23 = -__qd3;
        let __t24 = -__qd2 - __qd3;
        let __t25 = __c3 * __t7 + __s3 * __t8 - __t22 * __t23;
        let __t26 = __t1 * __t7 + __c3 * __t8 + __t21 * __t23;
        let __t27 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t22);
        let __t28 = __T::from_f64(203.0 / 10000.0) * __t22;
        let __t29 = __T::from_f64(-(3001.0 / 20000.0)) * __t21
            - __T::from_f64(203.0 / 10000.0) * __t24;
        let __t30 = __c3 * __t11 + __s3 * __t13 + __t24 * __t29 - __t22 * __t28
            - __T::from_f64(-(3001.0 / 20000.0)) * __t26;
        let __t31 = __t22 * __t27 - __t21 * __t29
            + __T::from_f64(203.0 / 10000.0) * __t26 - __t14;
        let __t32 = __t1 * __t11 + __c3 * __t13 + __t21 * __t28 - __t24 * __t27
            + __T::from_f64(-(3001.0 / 20000.0)) * __t25;
        let __t33 = __T::from_f64(7.0 / 100.0) * __t24
            - __T::from_f64(-(141.0 / 10000.0)) * __t22;
        let __t34 = __T::from_f64(-(203.0 / 10000.0)) * __t22
            - __T::from_f64(7.0 / 100.0) * __t21;
        let __t35 = __T::from_f64(-(141.0 / 10000.0)) * __t21
            - __T::from_f64(-(203.0 / 10000.0)) * __t24;
        let __t36 = __T::from_f64(24.0 / 5.0)
            * (__t30 + __t24 * __t35 - __t22 * __t34
                - __T::from_f64(-(141.0 / 10000.0)) * __t26);
        let __t37 = __T::from_f64(24.0 / 5.0)
            * (__t31 + __t22 * __t33 - __t21 * __t35
                + __T::from_f64(-(203.0 / 10000.0)) * __t26
                - __T::from_f64(7.0 / 100.0) * __t25);
        let __t38 = __T::from_f64(24.0 / 5.0)
            * (__t32 + __t21 * __t34 - __t24 * __t33
                + __T::from_f64(-(141.0 / 10000.0)) * __t25);
        let __t39 = __c4 * __t21 + __s4 * __t24;
        let __t40 = __t2 * __t21 + __c4 * __t24;
        let __t41 = -__t40;
        let __t42 = __t22 + __qd4;
        let __t43 = __c4 * __t25 - __qd4 * __t41;
        let __t44 = __qd4 * __t39 - __t2 * __t25;
        let __t45 = -(__T::from_f64(2159.0 / 5000.0) * __t41);
        let __t46 = __T::from_f64(2159.0 / 5000.0) * __t39;
        let __t47 = __c4 * __t30 + __s4 * __t31 + __t42 * __t46
            - __T::from_f64(2159.0 / 5000.0) * __t44;
        let __t48 = __t32 + __t41 * __t45 - __t39 * __t46;
        let __t49 = __T::from_f64(2159.0 / 5000.0) * __t43 - __t42 * __t45
            - (__t2 * __t30 + __c4 * __t31);
        let __t50 = -(__T::from_f64(19.0 / 1000.0) * __t41);
        let __t51 = __T::from_f64(19.0 / 1000.0) * __t39;
        let __t52 = __T::from_f64(41.0 / 50.0)
            * (__t47 + __t42 * __t51 - __T::from_f64(19.0 / 1000.0) * __t44);
        let __t53 = __T::from_f64(41.0 / 50.0)
            * (__t49 + __T::from_f64(19.0 / 1000.0) * __t43 - __t42 * __t50);
        let __t54 = __c5 * __t47 + __s5 * __t48;
        let __t55 = __t3 * __t47 + __c5 * __t48;
        let __t56 = -__t49;
        let __t57 = __c5 * __t39 + __s5 * __t42;
        let __t58 = __t3 * __t39 + __c5 * __t42;
        let __t59 = -__t44;
        let __t60 = __t40 - __qd5;
        let __t61 = __c5 * __t43 + __s5 * __t26 - __t58 * (-__qd5);
        let __t62 = __c6 * __t57 + __s6 * __t60;
        let __t63 = __t4 * __t57 + __c6 * __t60;
        let __t64 = __t58 + __qd6;
        let __t65 = __T::from_f64(4.0 / 125.0) * __t63;
        let __t66 = -(__T::from_f64(4.0 / 125.0) * __t62);
        let __t67 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t54 + __s6 * __t56
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t61 + __c6 * __t59 - __qd6 * __t62) - __t64 * __t66);
        let __t68 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t54 + __c6 * __t56 + __t64 * __t65
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t61 + __s6 * __t59 + __qd6 * __t63));
        let __t69 = -(__T::from_f64(4.0 / 125.0) * __t68);
        let __t70 = __T::from_f64(4.0 / 125.0) * __t67;
        let __t71 = __c6 * __t69 + __t4 * __t70;
        let __t72 = __s6 * __t69 + __c6 * __t70;
        let __t73 = __T::from_f64(17.0 / 50.0) * __t54 + __c6 * __t67 + __t4 * __t68;
        let __t74 = __T::from_f64(17.0 / 50.0) * __t55
            + __T::from_f64(9.0 / 100.0) * (__t55 + __t62 * __t66 - __t63 * __t65);
        let __t5_2 = -__t72;
        let __t4_2 = __s5 * __t71;
        let __t75 = __t52 + __c5 * __t73 + __t3 * __t74;
        let __t76 = __t53
            - (__T::from_f64(17.0 / 50.0) * __t56 + __s6 * __t67 + __c6 * __t68);
        let __t77 = __T::from_f64(19.0 / 1000.0) * __t53 + __c5 * __t71
            + __T::from_f64(2159.0 / 5000.0) * __t76;
        let __t78 = -__t76;
        let __t79 = -(-(__T::from_f64(19.0 / 1000.0) * __t52) - __t72
            - __T::from_f64(2159.0 / 5000.0) * __t75);
        let __t80 = __t36 + __c4 * __t75 + __t2 * __t78;
        let __t81 = __t37 + __s4 * __t75 + __c4 * __t78;
        let __t82 = __t38
            + __T::from_f64(41.0 / 50.0) * (__t48 + __t41 * __t50 - __t39 * __t51)
            + __s5 * __t73 + __c5 * __t74;
        let __t83 = __T::from_f64(-(141.0 / 10000.0)) * __t38
            - __T::from_f64(7.0 / 100.0) * __t37 + __c4 * __t77 + __t2 * __t79
            + __T::from_f64(-(3001.0 / 20000.0)) * __t82;
        let __t84 = __T::from_f64(7.0 / 100.0) * __t36
            - __T::from_f64(-(203.0 / 10000.0)) * __t38 + __s4 * __t77 + __c4 * __t79
            - __T::from_f64(203.0 / 10000.0) * __t82;
        let __t85 = __T::from_f64(-(203.0 / 10000.0)) * __t37
            - __T::from_f64(-(141.0 / 10000.0)) * __t36 + __t4_2
            + __T::from_f64(203.0 / 10000.0) * __t81
            - __T::from_f64(-(3001.0 / 20000.0)) * __t80;
        let __t3_2 = -__t84;
        let __t2_2 = __T::from_f64(-(1819.0 / 5000.0)) * __t19
            - __T::from_f64(3.0 / 500.0) * __t18 - __t84
            + __T::from_f64(2159.0 / 5000.0) * (__t19 + __s3 * __t80 + __c3 * __t82);
        let __t1_2 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t20 - __T::from_f64(91.0 / 400.0) * __t19
                + __c3 * __t83 + __t1 * __t85)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t18
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t20 + __s3 * __t83
                    + __c3 * __t85 - __T::from_f64(2159.0 / 5000.0) * (__t20 - __t81));
        let __t6_2 = __T::from_f64(0.0);
        ::planar_arm::__private::vector([__t1_2, __t2_2, __t3_2, __t4_2, __t5_2, __t6_2])
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
        let __t14 = __T::from_f64(91.0 / 400.0) * __t6
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t15 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t5;
        let __t16 = __T::from_f64(3.0 / 500.0) * __t5
            - __T::from_f64(-(1819.0 / 5000.0)) * __t6;
        let __t17 = __T::from_f64(87.0 / 5.0)
            * (__t12 + __t6 * __t16 - __qd2 * __t15
                + __T::from_f64(91.0 / 400.0) * __t8);
        let __t18 = __T::from_f64(87.0 / 5.0)
            * (__t13 + __qd2 * __t14 - __t5 * __t16
                - __T::from_f64(91.0 / 400.0) * __t7);
        let __t19 = __T::from_f64(87.0 / 5.0)
            * (__t11 + __t5 * __t15 - __t6 * __t14 + __T::from_f64(3.0 / 500.0) * __t7
                - __T::from_f64(-(1819.0 / 5000.0)) * __t8);
        let __t20 = __c3 * __t5 + __s3 * __t6;
        let __t21 = __t1 * __t5 + __c3 * __t6;
        let __t22 = -__qd3;
        let __t23 = -__qd2 - __qd3;
        let __t24 = __c3 * __t7 + __s3 * __t8 - __t21 * __t22;
        let __t25 = __t1 * __t7 + __c3 * __t8 + __t20 * __t22;
        let __t26 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t21);
        let __t27 = __T::from_f64(203.0 / 10000.0) * __t21;
        let __t28 = __T::from_f64(-(3001.0 / 20000.0)) * __t20
            - __T::from_f64(203.0 / 10000.0) * __t23;
        let __t29 = __c3 * __t12 + __s3 * __t13 + __t23 * __t28 - __t21 * __t27
            - __T::from_f64(-(3001.0 / 20000.0)) * __t25;
        let __t30 = __t21 * __t26 - __t20 * __t28
            + __T::from_f64(203.0 / 10000.0) * __t25 - __t11;
        let __t31 = __t1 * __t12 + __c3 * __t13 + __t20 * __t27 - __t23 * __t26
            + __T::from_f64(-(3001.0 / 20000.0)) * __t24;
        let __t32 = __T::from_f64(7.0 / 100.0) * __t23
            - __T::from_f64(-(141.0 / 10000.0)) * __t21;
        let __t33 = __T::from_f64(-(203.0 / 10000.0)) * __t21
            - __T::from_f64(7.0 / 100.0) * __t20;
        let __t34 = __T::from_f64(-(141.0 / 10000.0)) * __t20
            - __T::from_f64(-(203.0 / 10000.0)) * __t23;
        let __t35 = __T::from_f64(24.0 / 5.0)
            * (__t29 + __t23 * __t34 - __t21 * __t33
                - __T::from_f64(-(141.0 / 10000.0)) * __t25);
        let __t36 = __T::from_f64(24.0 / 5.0)
            * (__t30 + __t21 * __t32 - __t20 * __t34
                + __T::from_f64(-(203.0 / 10000.0)) * __t25
                - __T::from_f64(7.0 / 100.0) * __t24);
        let __t37 = __T::from_f64(24.0 / 5.0)
            * (__t31 + __t20 * __t33 - __t23 * __t32
                + __T::from_f64(-(141.0 / 10000.0)) * __t24);
        let __t38 = __c4 * __t20 + __s4 * __t23;
        let __t39 = __t2 * __t20 + __c4 * __t23;
        let __t40 = -__t39;
        let __t41 = __t21 + __qd4;
        let __t42 = __c4 * __t24 - __qd4 * __t40;
        let __t43 = __qd4 * __t38 - __t2 * __t24;
        let __t44 = -(__T::from_f64(2159.0 / 5000.0) * __t40);
        let __t45 = __T::from_f64(2159.0 / 5000.0) * __t38;
        let __t46 = __c4 * __t29 + __s4 * __t30 + __t41 * __t45
            - __T::from_f64(2159.0 / 5000.0) * __t43;
        let __t47 = __t31 + __t40 * __t44 - __t38 * __t45;
        let __t48 = __T::from_f64(2159.0 / 5000.0) * __t42 - __t41 * __t44
            - (__t2 * __t29 + __c4 * __t30);
        let __t49 = -(__T::from_f64(19.0 / 1000.0) * __t40);
        let __t50 = __T::from_f64(19.0 / 1000.0) * __t38;
        let __t51 = __T::from_f64(41.0 / 50.0)
            * (__t46 + __t41 * __t50 - __T::from_f64(19.0 / 1000.0) * __t43);
        let __t52 = __T::from_f64(41.0 / 50.0)
            * (__t48 + __T::from_f64(19.0 / 1000.0) * __t42 - __t41 * __t49);
        let __t53 = __c5 * __t46 + __s5 * __t47;
        let __t54 = __t3 * __t46 + __c5 * __t47;
        let __t55 = -__t48;
        let __t56 = __c5 * __t38 + __s5 * __t41;
        let __t57 = __t3 * __t38 + __c5 * __t41;
        let __t58 = -__t43;
        let __t59 = __t39 - __qd5;
        let __t60 = __c5 * __t42 + __s5 * __t25 - __t57 * (-__qd5);
        let __t61 = __c6 * __t56 + __s6 * __t59;
        let __t62 = __t4 * __t56 + __c6 * __t59;
        let __t63 = __t57 + __qd6;
        let __t64 = __T::from_f64(4.0 / 125.0) * __t62;
        let __t65 = -(__T::from_f64(4.0 / 125.0) * __t61);
        let __t66 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t53 + __s6 * __t55
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t60 + __c6 * __t58 - __qd6 * __t61) - __t63 * __t65);
        let __t67 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t53 + __c6 * __t55 + __t63 * __t64
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t60 + __s6 * __t58 + __qd6 * __t62));
        let __t68 = -(__T::from_f64(4.0 / 125.0) * __t67);
        let __t69 = __T::from_f64(4.0 / 125.0) * __t66;
        let __t70 = __c6 * __t68 + __t4 * __t69;
        let __t71 = __s6 * __t68 + __c6 * __t69;
        let __t72 = __T::from_f64(17.0 / 50.0) * __t53 + __c6 * __t66 + __t4 * __t67;
        let __t73 = __T::from_f64(17.0 / 50.0) * __t54
            + __T::from_f64(9.0 / 100.0) * (__t54 + __t61 * __t65 - __t62 * __t64);
        let __t5_2 = -__t71;
        let __t4_2 = __s5 * __t70;
        let __t74 = __t51 + __c5 * __t72 + __t3 * __t73;
        let __t75 = __t52
            - (__T::from_f64(17.0 / 50.0) * __t55 + __s6 * __t66 + __c6 * __t67);
        let __t76 = __T::from_f64(19.0 / 1000.0) * __t52 + __c5 * __t70
            + __T::from_f64(2159.0 / 5000.0) * __t75;
        let __t77 = -__t75;
        let __t78 = -(-(__T::from_f64(19.0 / 1000.0) * __t51) - __t71
            - __T::from_f64(2159.0 / 5000.0) * __t74);
        let __t79 = __t35 + __c4 * __t74 + __t2 * __t77;
        let __t80 = __t36 + __s4 * __t74 + __c4 * __t77;
        let __t81 = __t37
            + __T::from_f64(41.0 / 50.0) * (__t47 + __t40 * __t49 - __t38 * __t50)
            + __s5 * __t72 + __c5 * __t73;
        let __t82 = __T::from_f64(-(141.0 / 10000.0)) * __t37
            - __T::from_f64(7.0 / 100.0) * __t36 + __c4 * __t76 + __t2 * __t78
            + __T::from_f64(-(3001.0 / 20000.0)) * __t81;
        let __t83 = __T::from_f64(7.0 / 100.0) * __t35
            - __T::from_f64(-(203.0 / 10000.0)) * __t37 + __s4 * __t76 + __c4 * __t78
            - __T::from_f64(203.0 / 10000.0) * __t81;
        let __t84 = __T::from_f64(-(203.0 / 10000.0)) * __t36
            - __T::from_f64(-(141.0 / 10000.0)) * __t35 + __t4_2
            + __T::from_f64(203.0 / 10000.0) * __t80
            - __T::from_f64(-(3001.0 / 20000.0)) * __t79;
        let __t3_2 = -__t83;
        let __t2_2 = __T::from_f64(-(1819.0 / 5000.0)) * __t18
            - __T::from_f64(3.0 / 500.0) * __t17 - __t83
            + __T::from_f64(2159.0 / 5000.0) * (__t18 + __s3 * __t79 + __c3 * __t81);
        let __t1_2 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t19 - __T::from_f64(91.0 / 400.0) * __t18
                + __c3 * __t82 + __t1 * __t84)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t17
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t19 + __s3 * __t82
                    + __c3 * __t84 - __T::from_f64(2159.0 / 5000.0) * (__t19 - __t80));
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
        let __t91 = __T::from_f64(91.0 / 400.0) * __t83
            - __T::from_f64(3.0 / 500.0) * __qd2;
        let __t92 = __T::from_f64(-(1819.0 / 5000.0)) * __qd2
            - __T::from_f64(91.0 / 400.0) * __t82;
        let __t93 = __T::from_f64(3.0 / 500.0) * __t82
            - __T::from_f64(-(1819.0 / 5000.0)) * __t83;
        let __t94 = __T::from_f64(87.0 / 5.0)
            * (__t89 + __t83 * __t93 - __qd2 * __t92
                + __T::from_f64(91.0 / 400.0) * __t85);
        let __t95 = __T::from_f64(87.0 / 5.0)
            * (__t90 + __qd2 * __t91 - __t82 * __t93
                - __T::from_f64(91.0 / 400.0) * __t84);
        let __t96 = __T::from_f64(87.0 / 5.0)
            * (__t88 + __t82 * __t92 - __t83 * __t91 + __T::from_f64(3.0 / 500.0) * __t84
                - __T::from_f64(-(1819.0 / 5000.0)) * __t85);
        let __t97 = __c3 * __t82 + __s3 * __t83;
        let __t98 = __t1 * __t82 + __c3 * __t83;
        let __t99 = -__qd3;
        let __t100 = -__qd2 - __qd3;
        let __t101 = __c3 * __t84 + __s3 * __t85 - __t98 * __t99;
        let __t102 = __t1 * __t84 + __c3 * __t85 + __t97 * __t99;
        let __t103 = -(__T::from_f64(-(3001.0 / 20000.0)) * __t98);
        let __t104 = __T::from_f64(203.0 / 10000.0) * __t98;
        let __t105 = __T::from_f64(-(3001.0 / 20000.0)) * __t97
            - __T::from_f64(203.0 / 10000.0) * __t100;
        let __t106 = __c3 * __t89 + __s3 * __t90 + __t100 * __t105 - __t98 * __t104
            - __T::from_f64(-(3001.0 / 20000.0)) * __t102;
        let __t107 = __t98 * __t103 - __t97 * __t105
            + __T::from_f64(203.0 / 10000.0) * __t102 - __t88;
        let __t108 = __t1 * __t89 + __c3 * __t90 + __t97 * __t104 - __t100 * __t103
            + __T::from_f64(-(3001.0 / 20000.0)) * __t101;
        let __t109 = __T::from_f64(7.0 / 100.0) * __t100
            - __T::from_f64(-(141.0 / 10000.0)) * __t98;
        let __t110 = __T::from_f64(-(203.0 / 10000.0)) * __t98
            - __T::from_f64(7.0 / 100.0) * __t97;
        let __t111 = __T::from_f64(-(141.0 / 10000.0)) * __t97
            - __T::from_f64(-(203.0 / 10000.0)) * __t100;
        let __t112 = __T::from_f64(24.0 / 5.0)
            * (__t106 + __t100 * __t111 - __t98 * __t110
                - __T::from_f64(-(141.0 / 10000.0)) * __t102);
        let __t113 = __T::from_f64(24.0 / 5.0)
            * (__t107 + __t98 * __t109 - __t97 * __t111
                + __T::from_f64(-(203.0 / 10000.0)) * __t102
                - __T::from_f64(7.0 / 100.0) * __t101);
        let __t114 = __T::from_f64(24.0 / 5.0)
            * (__t108 + __t97 * __t110 - __t100 * __t109
                + __T::from_f64(-(141.0 / 10000.0)) * __t101);
        let __t115 = __c4 * __t97 + __s4 * __t100;
        let __t116 = __t2 * __t97 + __c4 * __t100;
        let __t117 = -__t116;
        let __t118 = __t98 + __qd4;
        let __t119 = __c4 * __t101 - __qd4 * __t117;
        let __t120 = __qd4 * __t115 - __t2 * __t101;
        let __t121 = -(__T::from_f64(2159.0 / 5000.0) * __t117);
        let __t122 = __T::from_f64(2159.0 / 5000.0) * __t115;
        let __t123 = __c4 * __t106 + __s4 * __t107 + __t118 * __t122
            - __T::from_f64(2159.0 / 5000.0) * __t120;
        let __t124 = __t108 + __t117 * __t121 - __t115 * __t122;
        let __t125 = __T::from_f64(2159.0 / 5000.0) * __t119 - __t118 * __t121
            - (__t2 * __t106 + __c4 * __t107);
        let __t126 = -(__T::from_f64(19.0 / 1000.0) * __t117);
        let __t127 = __T::from_f64(19.0 / 1000.0) * __t115;
        let __t128 = __T::from_f64(41.0 / 50.0)
            * (__t123 + __t118 * __t127 - __T::from_f64(19.0 / 1000.0) * __t120);
        let __t129 = __T::from_f64(41.0 / 50.0)
            * (__t125 + __T::from_f64(19.0 / 1000.0) * __t119 - __t118 * __t126);
        let __t130 = __c5 * __t123 + __s5 * __t124;
        let __t131 = __t3 * __t123 + __c5 * __t124;
        let __t132 = -__t125;
        let __t133 = __c5 * __t115 + __s5 * __t118;
        let __t134 = __t3 * __t115 + __c5 * __t118;
        let __t135 = -__t120;
        let __t136 = __t116 - __qd5;
        let __t137 = __c5 * __t119 + __s5 * __t102 - __t134 * (-__qd5);
        let __t138 = __c6 * __t133 + __s6 * __t136;
        let __t139 = __t4 * __t133 + __c6 * __t136;
        let __t140 = __t134 + __qd6;
        let __t141 = __T::from_f64(4.0 / 125.0) * __t139;
        let __t142 = -(__T::from_f64(4.0 / 125.0) * __t138);
        let __t143 = __T::from_f64(9.0 / 100.0)
            * (__c6 * __t130 + __s6 * __t132
                + __T::from_f64(4.0 / 125.0)
                    * (__t4 * __t137 + __c6 * __t135 - __qd6 * __t138)
                - __t140 * __t142);
        let __t144 = __T::from_f64(9.0 / 100.0)
            * (__t4 * __t130 + __c6 * __t132 + __t140 * __t141
                - __T::from_f64(4.0 / 125.0)
                    * (__c6 * __t137 + __s6 * __t135 + __qd6 * __t139));
        let __t145 = -(__T::from_f64(4.0 / 125.0) * __t144);
        let __t146 = __T::from_f64(4.0 / 125.0) * __t143;
        let __t147 = __c6 * __t145 + __t4 * __t146;
        let __t148 = __s6 * __t145 + __c6 * __t146;
        let __t149 = __T::from_f64(17.0 / 50.0) * __t130 + __c6 * __t143 + __t4 * __t144;
        let __t150 = __T::from_f64(17.0 / 50.0) * __t131
            + __T::from_f64(9.0 / 100.0) * (__t131 + __t138 * __t142 - __t139 * __t141);
        let __h5 = -__t148;
        let __h4 = __s5 * __t147;
        let __t151 = __t128 + __c5 * __t149 + __t3 * __t150;
        let __t152 = __t129
            - (__T::from_f64(17.0 / 50.0) * __t132 + __s6 * __t143 + __c6 * __t144);
        let __t153 = __T::from_f64(19.0 / 1000.0) * __t129 + __c5 * __t147
            + __T::from_f64(2159.0 / 5000.0) * __t152;
        let __t154 = -__t152;
        let __t155 = -(-(__T::from_f64(19.0 / 1000.0) * __t128) - __t148
            - __T::from_f64(2159.0 / 5000.0) * __t151);
        let __t156 = __t112 + __c4 * __t151 + __t2 * __t154;
        let __t157 = __t113 + __s4 * __t151 + __c4 * __t154;
        let __t158 = __t114
            + __T::from_f64(41.0 / 50.0) * (__t124 + __t117 * __t126 - __t115 * __t127)
            + __s5 * __t149 + __c5 * __t150;
        let __t159 = __T::from_f64(-(141.0 / 10000.0)) * __t114
            - __T::from_f64(7.0 / 100.0) * __t113 + __c4 * __t153 + __t2 * __t155
            + __T::from_f64(-(3001.0 / 20000.0)) * __t158;
        let __t160 = __T::from_f64(7.0 / 100.0) * __t112
            - __T::from_f64(-(203.0 / 10000.0)) * __t114 + __s4 * __t153 + __c4 * __t155
            - __T::from_f64(203.0 / 10000.0) * __t158;
        let __t161 = __T::from_f64(-(203.0 / 10000.0)) * __t113
            - __T::from_f64(-(141.0 / 10000.0)) * __t112 + __h4
            + __T::from_f64(203.0 / 10000.0) * __t157
            - __T::from_f64(-(3001.0 / 20000.0)) * __t156;
        let __h3 = -__t160;
        let __h2 = __T::from_f64(-(1819.0 / 5000.0)) * __t95
            - __T::from_f64(3.0 / 500.0) * __t94 - __t160
            + __T::from_f64(2159.0 / 5000.0) * (__t95 + __s3 * __t156 + __c3 * __t158);
        let __h1 = __s2
            * (__T::from_f64(3.0 / 500.0) * __t96 - __T::from_f64(91.0 / 400.0) * __t95
                + __c3 * __t159 + __t1 * __t161)
            + __c2
                * (__T::from_f64(91.0 / 400.0) * __t94
                    - __T::from_f64(-(1819.0 / 5000.0)) * __t96 + __s3 * __t159
                    + __c3 * __t161 - __T::from_f64(2159.0 / 5000.0) * (__t96 - __t157));
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
            }),
        }
    };
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
