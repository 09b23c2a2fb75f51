//! The generated identification methods: the regressor, the standard parameters' values, the
//! base regressor and the base parameters' values, and the `impl Identification` that holds
//! them.
//!
//! The regressor's columns are evaluated by the Newton-Euler recursion with unit parameters
//! (`newton_euler_unit`): the torques are linear in the standard parameters, so the torques
//! of an arm whose parameters are all zero but one are that parameter's column. The kinematics
//! is shared between the columns. The base parameters come from exact elimination
//! ([`base_parameters_from_energies`]), done at compile time.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::emit::EmitError;
use crate::generate::{emit_fn, matrix, vector, Fn, Header, Param};
use crate::mechanics::{ArmSpec, LinkSpec, PayloadSpec};
use crate::methods::{Derived, Method};
use crate::paths::{F64, STR};
use crate::poly::Poly;
use crate::programs::unrolled::{newton_euler_unit, Unit};
use crate::regressor::{
    base_parameters_from_energies, standard_values, BaseParameters, Kind, Standard,
};
use crate::slp::{Emit, Id, Input, Program};

fn to_poly<C: Emit>(c: &C) -> Poly {
    c.parts()
        .into_iter()
        .fold(Poly::default(), |acc, (m, r)| acc + Poly::monomial(m, r))
}

/// The arm over the polynomials (a literal arm's values as constants).
pub(crate) fn poly_arm<C: Emit>(arm: &ArmSpec<C>) -> ArmSpec<Poly> {
    ArmSpec {
        links: arm
            .links
            .iter()
            .map(|l| LinkSpec {
                length: to_poly(&l.length),
                mass: to_poly(&l.mass),
                inertia: to_poly(&l.inertia),
                com: (to_poly(&l.com.0), to_poly(&l.com.1)),
                armature: to_poly(&l.armature),
                damping: to_poly(&l.damping),
                frictionloss: to_poly(&l.frictionloss),
                joint: l.joint,
                range: l.range.clone(),
            })
            .collect(),
        gravity: to_poly(&arm.gravity),
        payload: arm.payload.as_ref().map(|p| PayloadSpec {
            mass: to_poly(&p.mass),
            inertia: to_poly(&p.inertia),
            com: (to_poly(&p.com.0), to_poly(&p.com.1)),
        }),
    }
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
        }
    }
}

/// The longest arm that gets an `Identification` impl. The exact elimination grows about as
/// the fifth power of the links and runs unoptimised in a user's build: at 30 links the
/// user crate's clean rebuild takes 24 s with it and 16 s without (docs/performance.md),
/// inside the 90 s budget; longer chains would outgrow it.
pub const MAX_LINKS: usize = 30;

/// `impl ::planar_arm::Identification<N, P, B>` for the arm, or nothing when its lengths or
/// gravity are such that the groupings are not polynomials (see
/// [`base_parameters_from_energies`]) or it has more than [`MAX_LINKS`] links.
///
/// # Errors
/// If a constant does not fit in `f64`.
pub fn identification<C: Emit>(d: &Derived<C>, header: &Header) -> Result<TokenStream, EmitError> {
    if d.arm.links.len() > MAX_LINKS {
        return Ok(TokenStream::new());
    }
    let Some(id) = d.identification() else {
        return Ok(TokenStream::new());
    };
    let n = d.arm.links.len();
    let (pp, bb) = (id.parameters.len(), id.base.columns.len());
    let (nn, pl, bl) = (
        Literal::usize_unsuffixed(n),
        Literal::usize_unsuffixed(pp),
        Literal::usize_unsuffixed(bb),
    );
    let all: Vec<usize> = (0..pp).collect();
    let q = Param::Joints("q", Input::Q);
    let qd = Param::Joints("qd", Input::Qd);
    let qdd = Param::Joints("qdd", Input::Qdd);
    let names: Vec<&str> = id.parameters.iter().map(|s| s.name.as_str()).collect();
    let formulas: Vec<String> = (0..bb)
        .map(|b| id.base.formula(b, &id.parameters))
        .collect();
    let listing = |rows: &[String]| -> String {
        rows.iter()
            .enumerate()
            .map(|(k, r)| format!("{}. {r}\n", k + 1))
            .collect()
    };
    let standard_doc = format!(
        "The standard parameters, in column order: per link `zz` (moment of inertia about the \
         joint, kg m^2), `mx`, `my` (first moments m cx, m cy in the link's frame, kg m), then \
         the payload's (`zzp`, `mxp`, `myp` in the last link's frame), the masses (kg), and \
         per joint that has them armature `ia` (kg m^2), damping `fv` (N m s/rad) and \
         Coulomb friction `fc` (N m):\n\n{}",
        listing(&names.iter().map(|s| format!("`{s}`")).collect::<Vec<_>>())
    );
    let base_doc = format!(
        "The base parameters, each an exact combination of the standard ones found at compile \
         time by rational elimination on the regressor's columns:\n\n{}",
        listing(
            &formulas
                .iter()
                .map(|s| format!("`{s}`"))
                .collect::<Vec<_>>()
        )
    );
    let specs = [
        Fn {
            name: "regressor",
            generic: false,
            params: vec![q, qd, qdd],
            ret: quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #pl>),
            doc: format!("The regressor Y(q, qd, qdd): `Y * standard_parameters() == inverse_dynamics(q, qd, qdd)`. {standard_doc}"),
            method: d.regressor_method(&id.parameters, &all),
            touch: TokenStream::new(),
            finish: Box::new(move |ids| matrix(n, pp, ids)),
        },
        Fn {
            name: "standard_parameters",
            generic: false,
            params: vec![],
            ret: quote!(::planar_arm::nalgebra::SVector<#F64, #pl>),
            doc: format!("The arm's standard parameters now (run-time parameters read from their fields). {standard_doc}"),
            method: d.parameter_values_method(&id.parameters, None),
            touch: TokenStream::new(),
            finish: Box::new(vector),
        },
        Fn {
            name: "base_regressor",
            generic: false,
            params: vec![q, qd, qdd],
            ret: quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #bl>),
            doc: format!("The base regressor: the regressor's columns of the base parameters, `Y_b * base_parameters() == inverse_dynamics(q, qd, qdd)`. {base_doc}"),
            method: d.regressor_method(&id.parameters, &id.base.columns),
            touch: TokenStream::new(),
            finish: Box::new(move |ids| matrix(n, bb, ids)),
        },
        Fn {
            name: "base_parameters",
            generic: false,
            params: vec![],
            ret: quote!(::planar_arm::nalgebra::SVector<#F64, #bl>),
            doc: format!("The arm's base parameters now. {base_doc}"),
            method: d.parameter_values_method(&id.parameters, Some(&id.base)),
            touch: TokenStream::new(),
            finish: Box::new(vector),
        },
    ];
    let mut fns = Vec::new();
    for f in &specs {
        fns.push(emit_fn(n, f, None)?);
    }
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    Ok(quote! {
        #[automatically_derived]
        #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
        impl #impl_generics ::planar_arm::Identification<#nn, #pl, #bl> for #ty #where_clause {
            const PARAMETERS: [&'static #STR; #pl] = [#(#names),*];
            const BASE_PARAMETERS: [&'static #STR; #bl] = [#(#formulas),*];
            #(#fns)*
        }
    })
}
