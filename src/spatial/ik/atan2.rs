//! `atan2` for the joint angles, inlined: the C library's costs about 18 ns a call here (a
//! call, and checks for the last half ulp), and a solve reads about 20 angles, each from a
//! `(cos, sin)` pair it already holds. This one is Cephes' `atan` (Moshier; the
//! approximation Agner Fog's vector class library and the `wide` crate use): the octant by
//! comparisons, one division to a ratio of at most 0.66 in magnitude, a rational function of
//! degree 4/5 in its square. Within 2 ulp (or 2.3e-16 absolute) of the standard library's
//! (tested below), against the IK's 1e-9 that the poses must reach; no table, no `libm`.

use core::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI};

/// `pi/2` minus its `f64`, `FRAC_PI_2`: added back where the octant's offset is `pi/2`.
const PI_2_LOW: f64 = 6.123_233_995_736_766e-17;

const P: [f64; 5] = [
    -8.750_608_600_031_904e-1,
    -1.615_753_718_733_365e1,
    -7.500_855_792_314_705e1,
    -1.228_866_684_490_136e2,
    -6.485_021_904_942_025e1,
];
/// The denominator's coefficients below its leading `z^5`.
const Q: [f64; 5] = [
    2.485_846_490_142_306e1,
    1.650_270_098_316_988e2,
    4.328_810_604_912_903e2,
    4.853_903_996_359_137e2,
    1.945_506_571_482_614e2,
];

/// The angle of `(x, y)` in `[-pi, pi]`, as `y.atan2(x)` for finite arguments, but `0` for
/// `(0, 0)` whatever the zeros' signs (as [`super::subproblems::Turn::of`] has it).
#[inline]
#[must_use]
pub(crate) fn atan2(y: f64, x: f64) -> f64 {
    let (ax, ay) = (x.abs(), y.abs());
    let swap = ay > ax;
    let (small, large) = if swap { (ax, ay) } else { (ay, ax) };
    // Now 0 <= small <= large and the angle in the first octant is atan(small / large).
    // Above a ratio of 0.66, atan(t) = pi/4 + atan((t - 1) / (t + 1)), and the second ratio
    // is at most 0.21 in magnitude.
    let upper = small > 0.66 * large;
    let (num, den) = if upper {
        (small - large, small + large)
    } else {
        (small, large)
    };
    if den == 0.0 {
        return 0.0;
    }
    let z = num / den;
    let zz = z * z;
    let p = (((P[0] * zz + P[1]) * zz + P[2]) * zz + P[3]) * zz + P[4];
    let q = ((((zz + Q[0]) * zz + Q[1]) * zz + Q[2]) * zz + Q[3]) * zz + Q[4];
    let mut a = z + z * (zz * p / q);
    if upper {
        a = FRAC_PI_4 + (a + 0.5 * PI_2_LOW);
    }
    if swap {
        a = FRAC_PI_2 - (a - PI_2_LOW);
    }
    if x < 0.0 {
        a = PI - (a - 2.0 * PI_2_LOW);
    }
    if y.is_sign_negative() {
        -a
    } else {
        a
    }
}

#[cfg(test)]
mod tests {
    use super::atan2;

    /// Whether `got` is within 2 ulp of `want` or 2.3e-16 of it.
    fn close(got: f64, want: f64) -> bool {
        let ulp = f64::EPSILON * want.abs();
        (got - want).abs() <= (2.0 * ulp).max(2.3e-16)
    }

    #[test]
    fn agrees_with_the_standard_library() {
        let mut state = 0x1234_5678_9abc_def0_u64;
        let mut unit = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1);
            ((state >> 11) as f64) / ((1_u64 << 53) as f64)
        };
        let mut worst = 0.0_f64;
        for k in 0..2_000_000 {
            // Ratios across many scales, and points near the axes and the diagonals.
            let (mut y, mut x) = (2.0 * unit() - 1.0, 2.0 * unit() - 1.0);
            match k % 4 {
                1 => y *= 10f64.powi(-((unit() * 20.0) as i32)),
                2 => x *= 10f64.powi(-((unit() * 20.0) as i32)),
                3 => y = x.abs().copysign(y) * (1.0 + (unit() - 0.5) * 1e-6),
                _ => {}
            }
            let (got, want) = (atan2(y, x), y.atan2(x));
            worst = worst.max((got - want).abs() / (f64::EPSILON * want.abs()).max(1e-300));
            assert!(
                close(got, want),
                "atan2({y:e}, {x:e}) = {got:e}, not {want:e}"
            );
        }
        eprintln!("worst {worst:.2} ulp");
        for (y, x) in [
            (0.0, 1.0),
            (1.0, 0.0),
            (0.0, -1.0),
            (-1.0, 0.0),
            (1.0, 1.0),
            (-1.0, -1.0),
            (1e-300, -1.0),
            (-1e-300, -1.0),
            (3.0, -3.0),
            (0.66, 1.0),
            (1.0, 0.66),
        ] {
            assert!(close(atan2(y, x), y.atan2(x)), "{y} {x}");
        }
        assert_eq!(atan2(0.0, 0.0), 0.0);
        assert_eq!(atan2(-0.0, -0.0), 0.0);
        assert_eq!(atan2(0.0, 2.0), 0.0);
    }
}
