//! Rigid transformations and mass properties of a model file, exact where they can be.
//!
//! A file's numbers are decimals, so they are exact rationals. A rotation is kept as the
//! roll-pitch-yaw the derive's `origin(..)` convention takes; where two frames are composed (a
//! fixed joint merged into the next) or a body is turned into another frame, the result is exact
//! when every rotation involved has rational entries (multiples of `pi/2`, and the few others
//! `FixedAngle::cos_sin` knows), and otherwise computed in `f64` and written back as the shortest
//! decimal that rounds to it: the value a user would type by hand.

use num_traits::{Signed, Zero};
use planar_arm_core::mechanics::spatial::FixedAngle;
use planar_arm_core::ring::{int, parse_decimal, to_f64, Rational};

pub type Vec3 = [Rational; 3];

/// The rational of the shortest decimal that rounds to `v` (finite).
pub fn decimal(v: f64) -> Rational {
    if v == 0.0 || !v.is_finite() {
        return int(0);
    }
    let r = parse_decimal(&format!("{:e}", v.abs())).unwrap_or_else(|| int(0));
    if v < 0.0 {
        -r
    } else {
        r
    }
}

fn f(r: &Rational) -> f64 {
    to_f64(r).unwrap_or(0.0)
}

fn zero3() -> Vec3 {
    [int(0), int(0), int(0)]
}

/// A rotation matrix, exact where its entries are rational.
#[derive(Clone, Debug)]
#[allow(clippy::large_enum_variant)] // a few per body, built once at compile time
pub enum Rotation {
    Exact([[Rational; 3]; 3]),
    Float([[f64; 3]; 3]),
}

impl Rotation {
    pub fn identity() -> Self {
        Self::Exact(core::array::from_fn(|i| {
            core::array::from_fn(|j| int(i64::from(i == j)))
        }))
    }

    /// `Rz(y) Ry(p) Rx(r)`, URDF's fixed-axis roll, pitch, yaw.
    pub fn rpy(rpy: &[FixedAngle; 3]) -> Self {
        let cs: Vec<(Option<Rational>, Option<Rational>, f64)> = rpy
            .iter()
            .map(|a| {
                let (c, s) = a.cos_sin();
                (c.as_rational(), s.as_rational(), a.value())
            })
            .collect();
        let exact = cs.iter().all(|(c, s, _)| c.is_some() && s.is_some());
        if exact {
            let g = |i: usize| {
                (
                    cs[i].0.clone().unwrap_or_default(),
                    cs[i].1.clone().unwrap_or_default(),
                )
            };
            let ((cr, sr), (cp, sp), (cy, sy)) = (g(0), g(1), g(2));
            Self::Exact([
                [
                    &cy * &cp,
                    &cy * &sp * &sr - &sy * &cr,
                    &cy * &sp * &cr + &sy * &sr,
                ],
                [
                    &sy * &cp,
                    &sy * &sp * &sr + &cy * &cr,
                    &sy * &sp * &cr - &cy * &sr,
                ],
                [-sp.clone(), &cp * &sr, &cp * &cr],
            ])
        } else {
            let (r, p, y) = (cs[0].2, cs[1].2, cs[2].2);
            let ((sr, cr), (sp, cp), (sy, cy)) = (r.sin_cos(), p.sin_cos(), y.sin_cos());
            Self::Float([
                [cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                [-sp, cp * sr, cp * cr],
            ])
        }
    }

    /// The rotation of the unit quaternion `(w, x, y, z)` (normalised here), as MuJoCo's `quat`.
    pub fn quaternion(q: &[Rational; 4]) -> Self {
        let n2: Rational = q.iter().map(|x| x * x).sum();
        if n2.is_zero() {
            return Self::identity();
        }
        let [w, x, y, z] = q.clone();
        let two = int(2);
        // R = I + 2 (w [v]x + [v]x^2) / |q|^2: rational in the quaternion's entries.
        let e = |a: Rational| a * &two / &n2;
        Self::Exact([
            [
                int(1) - e(&y * &y + &z * &z),
                e(&x * &y - &w * &z),
                e(&x * &z + &w * &y),
            ],
            [
                e(&x * &y + &w * &z),
                int(1) - e(&x * &x + &z * &z),
                e(&y * &z - &w * &x),
            ],
            [
                e(&x * &z - &w * &y),
                e(&y * &z + &w * &x),
                int(1) - e(&x * &x + &y * &y),
            ],
        ])
    }

    /// The rotation by `angle` about the unit `axis` (Rodrigues).
    pub fn axis_angle(axis: &[f64; 3], angle: &FixedAngle) -> Self {
        let (c, s) = angle.cos_sin();
        let n = axis.iter().map(|x| x * x).sum::<f64>().sqrt();
        let u = axis.map(|x| x / n);
        let exact_axis = axis.iter().filter(|x| **x != 0.0).count() == 1;
        if let (Some(c), Some(s), true) = (c.as_rational(), s.as_rational(), exact_axis) {
            // About a coordinate axis: entries 0, +-1, c, +-s.
            let k = u.iter().position(|x| *x != 0.0).unwrap_or(2);
            let s = if u[k] < 0.0 { -s } else { s };
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            let mut m: [[Rational; 3]; 3] = Default::default();
            m[k][k] = int(1);
            m[i][i] = c.clone();
            m[j][j] = c;
            m[j][i] = s.clone();
            m[i][j] = -s;
            return Self::Exact(m);
        }
        let (s, c) = angle.value().sin_cos();
        let t = 1.0 - c;
        let [x, y, z] = u;
        Self::Float([
            [t * x * x + c, t * x * y - s * z, t * x * z + s * y],
            [t * x * y + s * z, t * y * y + c, t * y * z - s * x],
            [t * x * z - s * y, t * y * z + s * x, t * z * z + c],
        ])
    }

    pub fn float(&self) -> [[f64; 3]; 3] {
        match self {
            Self::Exact(m) => m.clone().map(|row| row.map(|x| f(&x))),
            Self::Float(m) => *m,
        }
    }

    pub fn is_identity(&self) -> bool {
        match self {
            Self::Exact(m) => (0..3).all(|i| (0..3).all(|j| m[i][j] == int(i64::from(i == j)))),
            Self::Float(_) => false,
        }
    }

    pub fn mul(&self, other: &Self) -> Self {
        match (self, other) {
            (Self::Exact(a), Self::Exact(b)) => Self::Exact(core::array::from_fn(|i| {
                core::array::from_fn(|j| (0..3).map(|k| &a[i][k] * &b[k][j]).sum())
            })),
            _ => {
                let (a, b) = (self.float(), other.float());
                Self::Float(core::array::from_fn(|i| {
                    core::array::from_fn(|j| (0..3).map(|k| a[i][k] * b[k][j]).sum())
                }))
            }
        }
    }

    /// `R v`.
    pub fn apply(&self, v: &Vec3) -> Vec3 {
        match self {
            Self::Exact(m) => core::array::from_fn(|i| (0..3).map(|k| &m[i][k] * &v[k]).sum()),
            Self::Float(m) => {
                core::array::from_fn(|i| decimal((0..3).map(|k| m[i][k] * f(&v[k])).sum::<f64>()))
            }
        }
    }

    /// `R S R^T` of the symmetric `S` given as xx, yy, zz, xy, xz, yz.
    pub fn conjugate(&self, s: &[Rational; 6]) -> [Rational; 6] {
        let full = |s: &[Rational; 6]| {
            let [xx, yy, zz, xy, xz, yz] = s.clone();
            [
                [xx, xy.clone(), xz.clone()],
                [xy, yy, yz.clone()],
                [xz, yz, zz],
            ]
        };
        let pick = |m: [[Rational; 3]; 3]| {
            [
                m[0][0].clone(),
                m[1][1].clone(),
                m[2][2].clone(),
                m[0][1].clone(),
                m[0][2].clone(),
                m[1][2].clone(),
            ]
        };
        match self {
            Self::Exact(r) => {
                let a = full(s);
                pick(core::array::from_fn(|i| {
                    core::array::from_fn(|j| {
                        let mut acc = int(0);
                        for k in 0..3 {
                            for l in 0..3 {
                                acc += &r[i][k] * &a[k][l] * &r[j][l];
                            }
                        }
                        acc
                    })
                }))
            }
            Self::Float(r) => {
                let a = full(s).map(|row| row.map(|x| f(&x)));
                pick(core::array::from_fn(|i| {
                    core::array::from_fn(|j| {
                        let mut acc = 0.0;
                        for k in 0..3 {
                            for l in 0..3 {
                                acc += r[i][k] * a[k][l] * r[j][l];
                            }
                        }
                        decimal(acc)
                    })
                }))
            }
        }
    }

    /// Roll, pitch, yaw with `Rz(y) Ry(p) Rx(r)` equal to this rotation: multiples of `pi/2`
    /// exactly where the rotation is exact and a signed permutation, else decimals.
    pub fn to_rpy(&self) -> [FixedAngle; 3] {
        let m = self.float();
        let pitch = (-m[2][0]).atan2(m[0][0].hypot(m[1][0]));
        let (roll, yaw) = if m[0][0].hypot(m[1][0]) < 1e-12 {
            // Gimbal lock: only roll - yaw (or + yaw) is fixed; put it all in yaw.
            (0.0, (-m[0][1]).atan2(m[1][1]))
        } else {
            (m[2][1].atan2(m[2][2]), m[1][0].atan2(m[0][0]))
        };
        let permutation = matches!(self, Self::Exact(e)
            if e.iter().flatten().all(|x| x.is_zero() || x.abs() == int(1)));
        [roll, pitch, yaw].map(|a| {
            let quarter = a / core::f64::consts::FRAC_PI_2;
            if permutation && (quarter - quarter.round()).abs() < 1e-9 {
                // `quarter` is a small integer (-2..=2): exact.
                #[allow(clippy::cast_possible_truncation)]
                let k = quarter.round() as i64;
                FixedAngle::pi(Rational::new(k.into(), 2.into()))
            } else {
                FixedAngle {
                    radians: decimal(a),
                    pi_multiple: int(0),
                }
            }
        })
    }
}

/// A frame relative to another: translate by `xyz`, then rotate by `rpy` (URDF's `origin`).
#[derive(Clone, Debug)]
pub struct Pose {
    pub xyz: Vec3,
    pub rpy: [FixedAngle; 3],
}

impl Pose {
    pub fn identity() -> Self {
        Self {
            xyz: zero3(),
            rpy: [FixedAngle::zero(), FixedAngle::zero(), FixedAngle::zero()],
        }
    }

    pub fn from_rotation(xyz: Vec3, r: &Rotation) -> Self {
        Self {
            xyz,
            rpy: if r.is_identity() {
                Self::identity().rpy
            } else {
                r.to_rpy()
            },
        }
    }

    pub fn rotation(&self) -> Rotation {
        if self.rpy.iter().all(|a| *a == FixedAngle::zero()) {
            Rotation::identity()
        } else {
            Rotation::rpy(&self.rpy)
        }
    }

    /// `self * other`: `other` given in this frame. Exact angles are kept where one side does
    /// not rotate.
    pub fn then(&self, other: &Self) -> Self {
        let r = self.rotation();
        let moved = r.apply(&other.xyz);
        let xyz = core::array::from_fn(|i| &self.xyz[i] + &moved[i]);
        let rpy = if r.is_identity() {
            other.rpy.clone()
        } else if other.rotation().is_identity() {
            self.rpy.clone()
        } else {
            return Self::from_rotation(xyz, &r.mul(&other.rotation()));
        };
        Self { xyz, rpy }
    }
}

/// A body's mass, centre of mass and inertia about it (xx, yy, zz, xy, xz, yz), in some frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Inertial {
    pub mass: Rational,
    pub com: Vec3,
    pub inertia: [Rational; 6],
}

impl Default for Inertial {
    fn default() -> Self {
        Self {
            mass: int(0),
            com: zero3(),
            inertia: Default::default(),
        }
    }
}

impl Inertial {
    /// The same body seen from the frame in which `pose` is given.
    pub fn moved(&self, pose: &Pose) -> Self {
        self.placed(&pose.xyz, &pose.rotation())
    }

    /// The same body seen from a frame in which its own is at `xyz`, turned by `r`.
    pub fn placed(&self, xyz: &Vec3, r: &Rotation) -> Self {
        let c = r.apply(&self.com);
        Self {
            mass: self.mass.clone(),
            com: core::array::from_fn(|i| &xyz[i] + &c[i]),
            inertia: if r.is_identity() {
                self.inertia.clone()
            } else {
                r.conjugate(&self.inertia)
            },
        }
    }

    /// The rigid union of two bodies in one frame (parallel-axis theorem, exactly).
    pub fn merged(&self, other: &Self) -> Self {
        let mass = &self.mass + &other.mass;
        if mass.is_zero() {
            return Self::default();
        }
        let com: Vec3 = core::array::from_fn(|i| {
            (&self.mass * &self.com[i] + &other.mass * &other.com[i]) / &mass
        });
        let shifted = |b: &Self| -> [Rational; 6] {
            let d: Vec3 = core::array::from_fn(|i| &b.com[i] - &com[i]);
            let d2: Rational = d.iter().map(|x| x * x).sum();
            let pairs = [(0, 0), (1, 1), (2, 2), (0, 1), (0, 2), (1, 2)];
            core::array::from_fn(|k| {
                let (a, c) = pairs[k];
                let diag = if a == c { d2.clone() } else { int(0) };
                &b.inertia[k] + &b.mass * (diag - &d[a] * &d[c])
            })
        };
        let (a, b) = (shifted(self), shifted(other));
        Self {
            mass,
            com,
            inertia: core::array::from_fn(|k| &a[k] + &b[k]),
        }
    }

    pub fn is_negative(&self) -> bool {
        self.mass.is_negative() || self.inertia[..3].iter().any(Signed::is_negative)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use planar_arm_core::ring::ratio;

    fn pi(k: i64, d: i64) -> FixedAngle {
        FixedAngle::pi(ratio(k, d))
    }

    #[test]
    fn quarter_turns_compose_exactly() {
        let a = Pose {
            xyz: [int(1), int(0), int(0)],
            rpy: [pi(1, 2), FixedAngle::zero(), FixedAngle::zero()],
        };
        let b = Pose {
            xyz: [int(0), int(2), int(0)],
            rpy: [FixedAngle::zero(), FixedAngle::zero(), pi(1, 2)],
        };
        let ab = a.then(&b);
        // Rx(pi/2) takes y to z.
        assert_eq!(ab.xyz, [int(1), int(0), int(2)]);
        // Rx(pi/2) Rz(pi/2) as an exact signed permutation, and back.
        let r = a.rotation().mul(&b.rotation());
        let back = Rotation::rpy(&ab.rpy);
        let (Rotation::Exact(r), Rotation::Exact(back)) = (r, back) else {
            panic!("not exact: {:?}", ab.rpy);
        };
        assert_eq!(r, back);
    }

    #[test]
    fn general_angles_round_trip_through_rpy() {
        let rpy = [0.3, -1.1, 2.5].map(|a| FixedAngle {
            radians: decimal(a),
            pi_multiple: int(0),
        });
        let m = Rotation::rpy(&rpy).float();
        let again = Rotation::rpy(&Rotation::Float(m).to_rpy()).float();
        for i in 0..3 {
            for j in 0..3 {
                assert!((m[i][j] - again[i][j]).abs() < 1e-15, "{m:?} {again:?}");
            }
        }
    }

    #[test]
    fn quaternion_matches_axis_angle() {
        // 90 degrees about z: w = x = cos 45, here unnormalised (1, 0, 0, 1).
        let q = Rotation::quaternion(&[int(1), int(0), int(0), int(1)]);
        let a = Rotation::axis_angle(&[0.0, 0.0, 1.0], &pi(1, 2));
        let (Rotation::Exact(q), Rotation::Exact(a)) = (q, a) else {
            panic!("not exact");
        };
        assert_eq!(q, a);
    }

    #[test]
    fn merging_two_points_gives_the_dumbbell() {
        // Unit masses at x = +-1: inertia 2 about y and z, 0 about x.
        let point = |x: i64| Inertial {
            mass: int(1),
            com: [int(x), int(0), int(0)],
            inertia: Default::default(),
        };
        let m = point(1).merged(&point(-1));
        assert_eq!(m.com, zero3());
        assert_eq!(m.inertia, [int(0), int(2), int(2), int(0), int(0), int(0)]);
    }

    #[test]
    fn turning_a_rod_swaps_its_moments() {
        let rod = Inertial {
            mass: int(2),
            com: [int(0), int(0), ratio(1, 2)],
            inertia: [int(3), int(3), int(1), int(0), int(0), int(0)],
        };
        // Rx(pi/2) turns z into -y.
        let pose = Pose {
            xyz: zero3(),
            rpy: [pi(1, 2), FixedAngle::zero(), FixedAngle::zero()],
        };
        let turned = rod.moved(&pose);
        assert_eq!(turned.com, [int(0), ratio(-1, 2), int(0)]);
        assert_eq!(turned.inertia[..3], [int(3), int(1), int(3)]);
    }
}
