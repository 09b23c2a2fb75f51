//! Identification: the regressor and base parameters, derived exactly ([`regressor`]), and the
//! programs of the identification methods. The regressor's columns are evaluated by the
//! Newton-Euler recursion with unit parameters: the torques are linear in the standard
//! parameters, so the torques of an arm whose parameters are all zero but one are that
//! parameter's column, and the kinematics is shared between the columns.

use super::{Derived, Method};
use crate::mechanics::ArmSpec;
use crate::poly::Poly;
use crate::programs::unrolled::{newton_euler_unit, Unit};
use crate::slp::{Emit, Id, Input, Program};
use regressor::{base_parameters_from_energies, standard_values, BaseParameters, Kind, Standard};

mod modular;
pub mod regressor;
pub mod spatial;

fn to_poly<C: Emit>(c: &C) -> Poly {
    c.parts()
        .into_iter()
        .fold(Poly::default(), |acc, (m, r)| acc + Poly::monomial(m, r))
}

/// The arm over the polynomials (a literal arm's values as constants).
pub(crate) fn poly_arm<C: Emit>(arm: &ArmSpec<C>) -> ArmSpec<Poly> {
    arm.map(to_poly)
}

/// An arm's standard parameters and base parameters.
#[derive(Clone, Debug)]
pub struct Identification {
    /// The standard parameters, in the regressor's column order.
    pub parameters: Vec<Standard>,
    /// The base parameters.
    pub base: BaseParameters<Poly>,
}

impl<C: Emit> Derived<C> {
    /// The standard and base parameters; `None` when gravity is a run-time parameter (the
    /// groupings would not all be polynomials in it). With run-time lengths the groupings are
    /// polynomials in them.
    #[must_use]
    pub fn identification(&self) -> Option<Identification> {
        let (parameters, base) = base_parameters_from_energies(&poly_arm(&self.arm))?;
        Some(Identification { parameters, base })
    }

    /// The regressor columns of `parameters[k]` for `k` in `columns`, row-major
    /// (`y{row}_{column}`).
    #[must_use]
    pub fn regressor_method(&self, parameters: &[Standard], columns: &[usize]) -> Method {
        let n = self.arm.links.len();
        let mut p = Program::new();
        let zero = p.constant(crate::ring::int(0));
        let mut cols: Vec<Vec<Id>> = Vec::new();
        for &k in columns {
            let s = &parameters[k];
            // The payload's parameters are measured in the last link's frame.
            let link = s.link.unwrap_or(n - 1);
            let unit = |u: Unit, p: &mut Program| newton_euler_unit(p, &self.arm, u);
            let col = match s.kind {
                Kind::Zz => unit(Unit::Zz(link), &mut p),
                Kind::Mx => unit(Unit::Mx(link), &mut p),
                Kind::My => unit(Unit::My(link), &mut p),
                Kind::Mass => unit(Unit::Mass(link), &mut p),
                Kind::Armature => unit(Unit::Armature(link), &mut p),
                Kind::Damping | Kind::Frictionloss => {
                    let qd = p.input(Input::Qd(link));
                    let x = if s.kind == Kind::Damping {
                        qd
                    } else {
                        p.sign(qd)
                    };
                    (0..n).map(|i| if i == link { x } else { zero }).collect()
                }
            };
            cols.push(col);
        }
        let mut outputs = Vec::new();
        for i in 0..n {
            for (c, col) in cols.iter().enumerate() {
                outputs.push((format!("y{}_{}", i + 1, c + 1), col[i]));
            }
        }
        Method {
            program: p,
            outputs,
            evaluation: "Evaluated by the recursive Newton-Euler algorithm unrolled for this \
                         arm, once per standard parameter with that parameter one and the \
                         others zero (the torques are linear in them), the kinematics shared."
                .into(),
            packed: None,
        }
    }

    /// The values of `parameters` (standard, or with `base`, the base parameters) from the
    /// arm's values.
    #[must_use]
    pub fn parameter_values_method(
        &self,
        parameters: &[Standard],
        base: Option<&BaseParameters<Poly>>,
    ) -> Method {
        let values = standard_values(&self.arm, parameters);
        let mut p = Program::new();
        let outputs = match base {
            None => values
                .iter()
                .zip(parameters)
                .map(|(v, s)| (s.name.clone(), p.coefficient(v)))
                .collect(),
            Some(base) => base
                .grouping
                .iter()
                .enumerate()
                .map(|(b, group)| {
                    // Numeric multipliers in the arm's own coefficients; those that are
                    // polynomials in run-time lengths over the polynomials.
                    let mut value = C::from_rational(crate::ring::int(0));
                    let mut poly = Poly::default();
                    for (k, x) in group {
                        match x.as_rational() {
                            Some(r) => value = value + values[*k].scale(&r),
                            None => poly = poly + to_poly(&values[*k]) * x.clone(),
                        }
                    }
                    let id = if poly == Poly::default() {
                        p.coefficient(&value)
                    } else {
                        p.coefficient(&(to_poly(&value) + poly))
                    };
                    (format!("b{}", b + 1), id)
                })
                .collect(),
        };
        Method {
            program: p,
            outputs,
            evaluation: String::new(),
            packed: None,
        }
    }
}
