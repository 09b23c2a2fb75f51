//! A spatial serial arm as the engine derives it: each joint's geometry in its convention, exact
//! (lengths polynomial in run-time parameters, angles rational multiples of `pi` or numbers of
//! radians), and the links' mass properties.

use crate::algebra::poly::{Param, Poly};
use crate::algebra::ring::{int, ratio, to_f64, Rational};
use crate::mechanics::planar::JointKind;

/// A constant angle of the geometry, `radians + pi_multiple pi`, both exact.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FixedAngle {
    /// The part in radians.
    pub radians: Rational,
    /// The part in multiples of `pi`.
    pub pi_multiple: Rational,
}

impl FixedAngle {
    /// Zero.
    #[must_use]
    pub fn zero() -> Self {
        Self {
            radians: int(0),
            pi_multiple: int(0),
        }
    }

    /// `k pi`.
    #[must_use]
    pub fn pi(k: Rational) -> Self {
        Self {
            radians: int(0),
            pi_multiple: k,
        }
    }

    /// The angle as an `f64`.
    #[must_use]
    pub fn value(&self) -> f64 {
        to_f64(&self.radians).unwrap_or(0.0)
            + to_f64(&self.pi_multiple).unwrap_or(0.0) * core::f64::consts::PI
    }

    /// `(cos, sin)`, exact where they are rational: at multiples of `pi/2` (0, 1, -1), and the
    /// cosine of `pi/3` or the sine of `pi/6` (and their turns). Otherwise a named constant
    /// (`cos(pi/4)`, `sin(0.3)`), exact in that symbol, whose value enters the generated code as
    /// the `f64` it rounds to.
    #[must_use]
    pub fn cos_sin(&self) -> (Poly, Poly) {
        let exact = |r: Option<Rational>, name: &str, value: f64| match r {
            Some(r) => Poly::constant(r),
            None => Poly::param(Param::constant(name, value)),
        };
        let (c, s) = if num_traits::Zero::is_zero(&self.radians) {
            rational_cos_sin(&self.pi_multiple)
        } else {
            (None, None)
        };
        let text = self.to_string();
        let v = self.value();
        (
            exact(c, &format!("cos({text})"), v.cos()),
            exact(s, &format!("sin({text})"), v.sin()),
        )
    }
}

/// `cos(k pi)` and `sin(k pi)` where they are rational.
fn rational_cos_sin(k: &Rational) -> (Option<Rational>, Option<Rational>) {
    // k = n / 6 turns (of pi) reduced into [0, 2): the rational values of cos and sin.
    let six = k * int(6);
    if !six.is_integer() {
        return (None, None);
    }
    let n = (six.to_integer() % 12 + 12) % 12;
    let n = i64::try_from(n).unwrap_or(0);
    let cos = match n {
        0 => Some(int(1)),
        2 | 10 => Some(ratio(1, 2)),
        3 | 9 => Some(int(0)),
        4 | 8 => Some(ratio(-1, 2)),
        6 => Some(int(-1)),
        _ => None,
    };
    let sin = match n {
        0 | 6 => Some(int(0)),
        1 | 5 => Some(ratio(1, 2)),
        3 => Some(int(1)),
        7 | 11 => Some(ratio(-1, 2)),
        9 => Some(int(-1)),
        _ => None,
    };
    (cos, sin)
}

impl core::fmt::Display for FixedAngle {
    /// `pi/2`, `-pi/4`, `0.3`, `0.1 + pi/2`.
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        use num_traits::{One, Signed, Zero};
        let pi = &self.pi_multiple;
        let pi_text = if pi.is_zero() {
            String::new()
        } else {
            let sign = if pi < &int(0) { "-" } else { "" };
            let a = pi.abs();
            let numer = if a.numer().is_one() {
                "pi".to_string()
            } else {
                format!("{}pi", a.numer())
            };
            if a.denom().is_one() {
                format!("{sign}{numer}")
            } else {
                format!("{sign}{numer}/{}", a.denom())
            }
        };
        match (self.radians.is_zero(), pi.is_zero()) {
            (true, true) => f.write_str("0"),
            (true, false) => f.write_str(&pi_text),
            (false, true) => write!(f, "{}", crate::algebra::ring::show(&self.radians)),
            (false, false) => write!(
                f,
                "{} + {pi_text}",
                crate::algebra::ring::show(&self.radians)
            ),
        }
    }
}

/// A joint's geometry in one of the three conventions (the run-time crate's `JointGeometry`
/// documents them).
#[derive(Clone, Debug, PartialEq, Eq)]
#[allow(clippy::large_enum_variant)] // a handful per arm, built once
pub enum SpatialGeometry {
    /// Standard Denavit-Hartenberg: `Rz(q + theta) Tz(d) Tx(a) Rx(alpha)`.
    Dh {
        /// Link length.
        a: Poly,
        /// Twist.
        alpha: FixedAngle,
        /// Offset.
        d: Poly,
        /// Angle offset.
        theta: FixedAngle,
    },
    /// Modified Denavit-Hartenberg: `Rx(alpha) Tx(a) Rz(q + theta) Tz(d)`.
    Mdh {
        /// Link length.
        a: Poly,
        /// Twist.
        alpha: FixedAngle,
        /// Offset.
        d: Poly,
        /// Angle offset.
        theta: FixedAngle,
    },
    /// URDF: `Txyz Rz(y) Ry(p) Rx(r)`, then the motion about or along `axis` (a unit vector,
    /// exact or by named constants).
    Urdf {
        /// The joint frame's origin.
        xyz: [Poly; 3],
        /// Roll, pitch, yaw.
        rpy: [FixedAngle; 3],
        /// The unit axis in the joint frame.
        axis: [Poly; 3],
    },
}

/// One joint, the link it moves, and the joint's parameters.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpatialJointSpec {
    /// Geometry.
    pub geometry: SpatialGeometry,
    /// Hinge or slide.
    pub kind: JointKind,
    /// Link mass.
    pub mass: Poly,
    /// Link centre of mass in the link frame.
    pub com: [Poly; 3],
    /// Inertia about the centre of mass in the link's axes: xx, yy, zz, xy, xz, yz.
    pub inertia: [Poly; 6],
    /// Range, if limited.
    pub range: Option<(Rational, Rational)>,
    /// Armature.
    pub armature: Poly,
    /// Damping.
    pub damping: Poly,
    /// Coulomb friction.
    pub frictionloss: Poly,
    /// The joint spring's stiffness: a torque `stiffness (q - springref)` toward `springref`
    /// (MuJoCo's), whose energy `stiffness (q - springref)^2 / 2` is part of the potential.
    pub stiffness: Poly,
    /// Where the spring is relaxed.
    pub springref: Poly,
}

impl SpatialJointSpec {
    /// Whether the joint has a spring.
    #[must_use]
    pub fn sprung(&self) -> bool {
        self.stiffness != Poly::default()
    }
}

/// A rigid body's mass properties in some frame: mass, centre of mass, and the inertia tensor
/// about the centre of mass in that frame's axes (xx, yy, zz, xy, xz, yz).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpatialBody {
    /// Mass.
    pub mass: Poly,
    /// Centre of mass.
    pub com: [Poly; 3],
    /// Inertia about the centre of mass: xx, yy, zz, xy, xz, yz.
    pub inertia: [Poly; 6],
}

impl SpatialBody {
    /// The body of joint `spec`'s link, in the link's frame.
    #[must_use]
    pub fn of_link(spec: &SpatialJointSpec) -> Self {
        Self {
            mass: spec.mass.clone(),
            com: spec.com.clone(),
            inertia: spec.inertia.clone(),
        }
    }

    /// The ten standard parameters in Pinocchio's order `[m, m cx, m cy, m cz, Jxx, Jxy, Jyy,
    /// Jxz, Jyz, Jzz]`, `J` the inertia about the frame's origin: `I + m (|c|^2 E - c c^T)`.
    #[must_use]
    pub fn standard_parameters(&self) -> [Poly; 10] {
        let m = &self.mass;
        let c = &self.com;
        let [xx, yy, zz, xy, xz, yz] = self.inertia.clone();
        let tensor = [
            [xx, xy.clone(), xz.clone()],
            [xy, yy, yz.clone()],
            [xz, yz, zz],
        ];
        let c2 = c
            .iter()
            .fold(Poly::default(), |acc, x| acc + x.clone() * x.clone());
        let j = |a: usize, b: usize| {
            let mut shift = Poly::default() - c[a].clone() * c[b].clone();
            if a == b {
                shift = shift + c2.clone();
            }
            tensor[a][b].clone() + m.clone() * shift
        };
        [
            m.clone(),
            m.clone() * c[0].clone(),
            m.clone() * c[1].clone(),
            m.clone() * c[2].clone(),
            j(0, 0),
            j(0, 1),
            j(1, 1),
            j(0, 2),
            j(1, 2),
            j(2, 2),
        ]
    }
}

/// A spatial arm: joints base first, gravity, the tool frame in the last link's frame.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SpatialArmSpec {
    /// The joints.
    pub joints: Vec<SpatialJointSpec>,
    /// Gravity in the base frame.
    pub gravity: [Poly; 3],
    /// The tool's origin in the last link's frame.
    pub tool_xyz: [Poly; 3],
    /// The tool's roll, pitch, yaw there.
    pub tool_rpy: [FixedAngle; 3],
    /// A payload held rigidly by the tool, in the tool frame.
    pub payload: Option<SpatialBody>,
}

impl SpatialArmSpec {
    /// The same arm with every length, mass property, joint parameter, gravity and tool offset
    /// mapped by `f` (angles and axes are kept).
    #[must_use]
    pub fn map_values(&self, f: impl Fn(&Poly) -> Poly) -> Self {
        let f3 = |v: &[Poly; 3]| -> [Poly; 3] { core::array::from_fn(|i| f(&v[i])) };
        let f6 = |v: &[Poly; 6]| -> [Poly; 6] { core::array::from_fn(|i| f(&v[i])) };
        let joints = self
            .joints
            .iter()
            .map(|j| SpatialJointSpec {
                geometry: match &j.geometry {
                    SpatialGeometry::Dh { a, alpha, d, theta } => SpatialGeometry::Dh {
                        a: f(a),
                        alpha: alpha.clone(),
                        d: f(d),
                        theta: theta.clone(),
                    },
                    SpatialGeometry::Mdh { a, alpha, d, theta } => SpatialGeometry::Mdh {
                        a: f(a),
                        alpha: alpha.clone(),
                        d: f(d),
                        theta: theta.clone(),
                    },
                    SpatialGeometry::Urdf { xyz, rpy, axis } => SpatialGeometry::Urdf {
                        xyz: f3(xyz),
                        rpy: rpy.clone(),
                        axis: axis.clone(),
                    },
                },
                kind: j.kind,
                mass: f(&j.mass),
                com: f3(&j.com),
                inertia: f6(&j.inertia),
                range: j.range.clone(),
                armature: f(&j.armature),
                damping: f(&j.damping),
                frictionloss: f(&j.frictionloss),
                stiffness: f(&j.stiffness),
                springref: f(&j.springref),
            })
            .collect();
        Self {
            joints,
            gravity: f3(&self.gravity),
            tool_xyz: f3(&self.tool_xyz),
            tool_rpy: self.tool_rpy.clone(),
            payload: self.payload.as_ref().map(|p| SpatialBody {
                mass: f(&p.mass),
                com: f3(&p.com),
                inertia: f6(&p.inertia),
            }),
        }
    }
}

/// The unit vector along `v` (not zero): exact when `|v|^2` is the square of a rational, else
/// each component a named constant `x/sqrt(n)`.
#[must_use]
pub fn unit_axis(v: &[Rational; 3]) -> [Poly; 3] {
    let n2: Rational = v.iter().map(|x| x * x).sum();
    if let Some(root) = rational_sqrt(&n2) {
        return v.clone().map(|x| Poly::constant(x / &root));
    }
    let n = to_f64(&n2).unwrap_or(1.0).sqrt();
    v.clone().map(|x| {
        if num_traits::Zero::is_zero(&x) {
            Poly::default()
        } else {
            let name = format!(
                "{}/sqrt({})",
                crate::algebra::ring::show(&x),
                crate::algebra::ring::show(&n2)
            );
            Poly::param(Param::constant(&name, to_f64(&x).unwrap_or(0.0) / n))
        }
    })
}

/// The rational square root of `r`, if it has one.
fn rational_sqrt(r: &Rational) -> Option<Rational> {
    let (n, d) = (r.numer(), r.denom());
    if n.sign() == num_bigint::Sign::Minus {
        return None;
    }
    let (sn, sd) = (n.sqrt(), d.sqrt());
    (&sn * &sn == *n && &sd * &sd == *d).then(|| Rational::new(sn, sd))
}
