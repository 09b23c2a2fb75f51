//! The `impl ::planar_arm::spatial::SpatialArm<N>` that `#[derive(SpatialArm)]` emits: the tool
//! and link poses, the Jacobian, gravity and potential energy as straight-line code (each the
//! cheaper of the product of transformations and the expanded formulas), `EXACT`, `model()`
//! and the closed-form inverse kinematics where the geometry allows one.

use proc_macro2::{Literal, TokenStream};
use quote::quote;

use crate::emission::function::{matrix, vector, Fn, Param};
use crate::emission::generate::frozen;
use crate::emission::header::Header;
use crate::emit::{coefficient_tokens, f64_tokens, formula_doc, local, EmitError};
use crate::expr::Expr;
use crate::mechanics::spatial::frames::EXPANSION_BUDGET;
use crate::mechanics::spatial::lagrangian::DYNAMICS_BUDGET;
use crate::mechanics::spatial::{
    decouple, Decoupling, FixedAngle, SpatialArmSpec, SpatialBody, SpatialGeometry,
};
use crate::mechanics::JointKind;
use crate::methods::spatial::SpatialDerived;
use crate::paths::{F64, STR};
use crate::poly::Poly;
use crate::slp::Input;

/// The complete impl.
///
/// # Errors
/// If a constant does not fit in `f64`, or an exact coefficient in the `i128` of `EXACT`.
pub fn generate_spatial(arm: &SpatialArmSpec, header: &Header) -> Result<TokenStream, EmitError> {
    let d = if header.exact_dynamics {
        SpatialDerived::with_exact_dynamics(arm)
    } else {
        SpatialDerived::new(arm)
    };
    if header.exact_dynamics && d.dynamics.is_none() {
        return Err(EmitError {
            message: format!(
                "`exact_dynamics` asks for M and c multiplied out, but this arm's tool pose \
                 already passes {EXPANSION_BUDGET} terms (twists or rotations that are not \
                 multiples of pi/2 at most joints), so its dynamics would not fit a build; \
                 remove the key (the derive then evaluates the products of the joints' \
                 transformations)"
            ),
        });
    }
    let n = arm.joints.len();
    let nn = Literal::usize_unsuffixed(n);
    let q = Param::Joints("q", Input::Q);
    let mut fns = Vec::new();
    let pose_doc = |title: &str| {
        let Some(k) = &d.kinematics else {
            return unexpanded_doc(title);
        };
        let rows: Vec<(String, &Expr<Poly>)> = (0..3)
            .flat_map(|i| (0..4).map(move |j| (i, j)))
            .map(|(i, j)| {
                if j < 3 {
                    (format!("R{}{}", i + 1, j + 1), &k.tool.r[i][j])
                } else {
                    (format!("p{}", i + 1), &k.tool.p[i])
                }
            })
            .collect();
        formula_doc(title, &rows)
    };
    // The joint fields hold nothing: read them once so that a user's crate is not told they
    // are never read.
    let fields = &header.fields;
    let touch = if fields.is_empty() {
        TokenStream::new()
    } else {
        quote!(let _ = (#(&self.#fields),*);)
    };
    fns.push(
        Fn::new(
            "tip_pose",
            vec![q],
            quote!(::planar_arm::nalgebra::Isometry3<#F64>),
            pose_doc("The tool frame in the base frame: rotation R and position p."),
            d.tip_pose.clone(),
            Box::new(isometry),
        )
        .in_f64()
        .touching(touch),
    );
    fns.push(
        Fn::new(
            "link_poses",
            vec![q],
            quote!([::planar_arm::nalgebra::Isometry3<#F64>; #nn]),
            "Each link's frame in the base frame, base first.".to_string(),
            d.link_poses.clone(),
            Box::new(|ids| {
                let poses = ids.chunks(12).map(isometry);
                quote!([#(#poses),*])
            }),
        )
        .in_f64(),
    );
    fns.push(Fn::new(
        "jacobian",
        vec![q],
        quote!(::planar_arm::nalgebra::SMatrix<__T, 6, #nn>),
        "The geometric Jacobian of the tool frame: rows 0-2 the linear velocity of its origin, \
         rows 3-5 the angular velocity, both in base coordinates (Pinocchio's \
         `LOCAL_WORLD_ALIGNED`)."
            .to_string(),
        d.jacobian.clone(),
        Box::new(move |ids| matrix(6, n, ids)),
    ));
    let g_title = "The gravity torques g = dV/dq (forces for slides) that hold the arm.";
    let v_title = "The potential energy, zero at the base origin.";
    let (g_doc, v_doc) = match &d.kinematics {
        Some(k) => {
            let g_rows: Vec<(String, &Expr<Poly>)> = k
                .gravity
                .iter()
                .enumerate()
                .map(|(i, e)| (format!("g{}", i + 1), e))
                .collect();
            (
                formula_doc(g_title, &g_rows),
                formula_doc(v_title, &[("V".to_string(), &k.potential_energy)]),
            )
        }
        None => (unexpanded_doc(g_title), unexpanded_doc(v_title)),
    };
    fns.push(Fn::new(
        "gravity",
        vec![q],
        quote!(::planar_arm::nalgebra::SVector<__T, #nn>),
        g_doc,
        d.gravity.clone(),
        Box::new(vector),
    ));
    fns.push(Fn::new(
        "potential_energy",
        vec![q],
        quote!(__T),
        v_doc,
        d.potential_energy.clone(),
        Box::new(|ids| {
            let v = &ids[0];
            quote!(#v)
        }),
    ));
    fns.push(Fn::new(
        "inverse_dynamics",
        vec![
            q,
            Param::Joints("qd", Input::Qd),
            Param::Joints("qdd", Input::Qdd),
        ],
        quote!(::planar_arm::nalgebra::SVector<__T, #nn>),
        "The joint forces tau = M qdd + c + g + f (torques for hinges, forces for slides), M \
         holding each joint's armature and f = damping qd + frictionloss sign(qd)."
            .to_string(),
        d.inverse_dynamics.clone(),
        Box::new(vector),
    ));
    let qd = Param::Joints("qd", Input::Qd);
    let v = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    let mm = quote!(::planar_arm::nalgebra::SMatrix<__T, #nn, #nn>);
    fns.push(Fn::new(
        "mass_matrix",
        vec![q],
        mm.clone(),
        dynamics_doc(
            "The mass matrix M(q), each joint's armature on its diagonal.",
            &d,
            true,
        ),
        d.mass_matrix.clone(),
        Box::new(move |ids| matrix(n, n, ids)),
    ));
    fns.push(Fn::new(
        "coriolis",
        vec![q, qd],
        v.clone(),
        dynamics_doc(
            "The velocity-product (Coriolis and centrifugal) forces c(q, qd).",
            &d,
            false,
        ),
        d.coriolis.clone(),
        Box::new(vector),
    ));
    fns.push(Fn::new(
        "coriolis_matrix",
        vec![q, qd],
        mm.clone(),
        "The Coriolis matrix C(q, qd) from Christoffel symbols: C qd = c, and Mdot - 2C is skew."
            .to_string(),
        d.coriolis_matrix.clone(),
        Box::new(move |ids| matrix(n, n, ids)),
    ));
    fns.push(Fn::new(
        "friction",
        vec![qd],
        v.clone(),
        "The joint friction f = damping qd + frictionloss sign(qd), sign(0) = 0.".to_string(),
        d.friction.clone(),
        Box::new(vector),
    ));
    fns.push(Fn::new(
        "bias",
        vec![q, qd],
        v.clone(),
        "The bias h = c + g + f.".to_string(),
        d.bias.clone(),
        Box::new(vector),
    ));
    fns.push(
        Fn::new(
            "mass_matrix_and_bias",
            vec![q, qd],
            quote!((#mm, #v)),
            "The mass matrix and the bias h = c + g + f in one program.".to_string(),
            d.mass_matrix_and_bias.clone(),
            Box::new(move |ids| {
                let m = matrix(n, n, &ids[..n * n]);
                let h = vector(&ids[n * n..]);
                quote!((#m, #h))
            }),
        )
        // The forward dynamics' derivatives compile it into their AVX2 and AVX-512 copies.
        .with_inlined_body(),
    );
    // The forward derivatives' reverse-mode body and the method that dispatches it.
    let mut adjoint = Vec::new();
    if let Some(method) = &d.inverse_dynamics_derivatives {
        let f64mat = quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>);
        let derivatives = |method: crate::methods::Method| {
            Fn::new(
                "inverse_dynamics_derivatives",
                vec![q, qd, Param::Joints("qdd", Input::Qdd)],
                quote!((#f64mat, #f64mat)),
                "The partial derivatives of `inverse_dynamics`, `(dtau/dq, dtau/dqd)` (`dtau/dqdd` \
                 is `mass_matrix`). Coulomb friction contributes 0 to `dtau/dqd`."
                    .to_string(),
                method,
                Box::new(move |ids| {
                    let dq = matrix(n, n, &ids[..n * n]);
                    let dqd = matrix(n, n, &ids[n * n..]);
                    quote!((#dq, #dqd))
                }),
            )
            .in_f64()
        };
        // The forward dynamics' products by -M^-1, with the same inputs and outputs' shape.
        if let Some(pk) = &d.forward_dynamics_adjoint {
            let mut f = derivatives(pk.values.clone());
            f.name = "forward_dynamics_derivatives";
            adjoint.push(super::function::adjoint_body(n, &f, pk)?);
            adjoint.push(wide_dispatch(n, &forward_derivatives_doc(&d, pk)));
        }
        fns.push(derivatives(method.clone()).dispatched("InverseDynamicsDerivatives", quote!(#nn)));
    }
    let mut body = Vec::with_capacity(fns.len() + 12);
    // The hot methods of an arm with run-time parameters read a block of its parameter-only
    // values that `freeze` computes once, as planar arms' do.
    let hot = frozen::hot(&fns);
    let split = frozen::split(&hot);
    for f in &fns {
        body.push(frozen::plain(n, f, &hot, split.as_ref())?);
    }
    body.extend(frozen::variants(n, &hot, split.as_ref())?);
    body.extend(solved(n, !adjoint.is_empty()));
    body.extend(adjoint);
    body.push(exact(n, &d)?);
    let (names, names_doc) = (&header.joint_names, &header.joint_names_doc);
    body.push(quote! {
        #[doc = #names_doc]
        const JOINT_NAMES: [&'static #STR; #nn] = [#(#names),*];
    });
    body.push(model(arm)?);
    body.push(inverse_kinematics(arm)?);
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    let (dynamics, body) = super::traits::split_dynamics(body);
    let identification = super::spatial_identification::spatial_identification(arm, header)?;
    Ok(quote! {
        #[automatically_derived]
        #[allow(clippy::nursery, clippy::approx_constant)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops); a model file's 1.5707963 is its value, not pi/2
        impl #impl_generics ::planar_arm::Dynamics<#nn> for #ty #where_clause {
            #(#dynamics)*
        }
        #[automatically_derived]
        #[allow(clippy::nursery, clippy::approx_constant)]
        impl #impl_generics ::planar_arm::spatial::SpatialArm<#nn> for #ty #where_clause {
            #(#body)*
        }
        #identification
    })
}

/// `forward_dynamics` and `kinetic_energy`, written as calls of the generated
/// `mass_matrix_and_bias` and `mass_matrix` and of the run-time crate: planar arms' `L D L^T`
/// solve (each pivot floored at 2^-52 `M_ii`) and quadratic form; and the forward dynamics'
/// derivatives in the dispatch's AVX2 and AVX-512 copies, the trait's default computed from the inlined body
/// of `mass_matrix_and_bias`, with the products by `-M^-1` from the reverse-mode program where
/// the arm has one (`adjoint`).
fn solved(n: usize, adjoint: bool) -> [TokenStream; 4] {
    let nn = Literal::usize_unsuffixed(n);
    let v = quote!(::planar_arm::nalgebra::SVector<__T, #nn>);
    let (q, qd, tau) = (local("q"), local("qd"), local("tau"));
    let (m, h) = (local("m"), local("h"));
    let lanes = if adjoint { local("lanes") } else { local("_") };
    let derivatives = if adjoint {
        quote!(::planar_arm::__private::forward_derivatives_in(
            self, #lanes, self.__mass_matrix_and_bias_body(#q, #qd), #q, #qd, #tau,
        ))
    } else {
        quote!(::planar_arm::__private::forward_derivatives(
            self, self.__mass_matrix_and_bias_body(#q, #qd), #q, #qd, #tau,
        ))
    };
    [
        quote! {
            /// The accelerations qdd that solve M qdd = tau - c - g - f: M and h = c + g + f from
            /// `mass_matrix_and_bias` (one program), then an L D L^T factorisation of M (no
            /// square roots, no allocation), each pivot floored at 2^-52 M_ii. An arm with a
            /// joint that moves no mass, inertia or armature has a singular M and accelerations
            /// that are not finite; `try_forward_dynamics` says so with an `Err`.
            #[inline]
            fn forward_dynamics<__T: ::planar_arm::Real>(&self, #q: &#v, #qd: &#v, #tau: &#v) -> #v {
                let (#m, #h) = self.mass_matrix_and_bias(#q, #qd);
                ::planar_arm::__private::forward_solve(
                    &#m, #tau, &#h, [::planar_arm::__private::Floor::Relative; #nn],
                )
            }
        },
        quote! {
            /// `forward_dynamics` from the frozen view's M and h.
            #[doc(hidden)]
            #[inline]
            fn __forward_dynamics_frozen<__T: ::planar_arm::Real>(
                &self,
                __block: &Self::__Frozen,
                #q: &#v,
                #qd: &#v,
                #tau: &#v,
            ) -> #v {
                let (#m, #h) = self.__mass_matrix_and_bias_frozen(__block, #q, #qd);
                ::planar_arm::__private::forward_solve(
                    &#m, #tau, &#h, [::planar_arm::__private::Floor::Relative; #nn],
                )
            }
        },
        quote! {
            /// The forward dynamics' derivatives in the dispatch's AVX2 and AVX-512 copies: the
            /// default's computation, with M and h compiled into each copy.
            #[doc(hidden)]
            #[inline(always)]
            fn __forward_dynamics_derivatives_packed<__L: ::planar_arm::__private::Lanes>(
                &self,
                #lanes: __L,
                #q: &::planar_arm::nalgebra::SVector<#F64, #nn>,
                #qd: &::planar_arm::nalgebra::SVector<#F64, #nn>,
                #tau: &::planar_arm::nalgebra::SVector<#F64, #nn>,
            ) -> (
                ::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>,
                ::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>,
                ::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>,
            ) {
                #derivatives
            }
        },
        quote! {
            /// The kinetic energy qd^T M qd / 2, J, armature included.
            #[inline]
            fn kinetic_energy<__T: ::planar_arm::Real>(&self, #q: &#v, #qd: &#v) -> __T {
                ::planar_arm::__private::kinetic_energy(&self.mass_matrix(#q), #qd)
            }
        },
    ]
}

/// `forward_dynamics_derivatives` through `__private::dispatch_wide`, whose third copy runs the
/// reverse-mode program eight rows to an AVX-512 register where the processor has AVX-512F.
fn wide_dispatch(n: usize, doc: &str) -> TokenStream {
    let nn = Literal::usize_unsuffixed(n);
    let (q, qd, tau) = (local("q"), local("qd"), local("tau"));
    let v = quote!(::planar_arm::nalgebra::SVector<#F64, #nn>);
    let m = quote!(::planar_arm::nalgebra::SMatrix<#F64, #nn, #nn>);
    quote! {
        #[doc = #doc]
        #[inline]
        fn forward_dynamics_derivatives(&self, #q: &#v, #qd: &#v, #tau: &#v) -> (#m, #m, #m) {
            ::planar_arm::__private::dispatch_wide(
                ::planar_arm::__private::ForwardDynamicsDerivatives::<Self, #nn> {
                    arm: self,
                    q: #q,
                    qd: #qd,
                    tau: #tau,
                },
            )
        }
    }
}

/// The docs of a spatial arm's `forward_dynamics_derivatives`: what it computes and the cost of
/// the route its optimised x86-64 copies take.
fn forward_derivatives_doc(d: &SpatialDerived, pk: &crate::packed::Packed) -> String {
    format!(
        "The partial derivatives of `forward_dynamics`, `(dqdd/dq, dqdd/dqd, dqdd/dtau)`, as \
         Pinocchio's `computeABADerivatives`: `-M^-1 dtau/dq`, `-M^-1 dtau/dqd` at `qdd = \
         forward_dynamics(q, qd, tau)`, and `M^-1`. NaN everywhere if M has no factor (only \
         with NaN or infinite input).\n\n\
         In optimised x86-64 builds, where the processor has AVX2 and FMA: `M` and `h` \
         ({}), one `L D L^T` factor of M for `qdd` and `M^-1`, then the inverse dynamics run \
         backward from the torques weighted by the rows of `-M^-1`: {} on scalars and {} \
         eight-lane operations ({} of them fused multiply-adds), one AVX-512 register per \
         eight rows where the processor has AVX-512F (in a build with the default target \
         flags), two AVX2 registers elsewhere. Other builds multiply \
         `inverse_dynamics_derivatives` at `qdd` by `-M^-1`.",
        d.mass_matrix_and_bias.op_count(),
        pk.values.op_count(),
        pk.lane_op_count(),
        pk.fused_count(),
    )
}

/// `__private::isometry3` of twelve outputs: the rotation row-major, then the position.
fn isometry(ids: &[proc_macro2::Ident]) -> TokenStream {
    let r = ids[..9].chunks(3).map(|row| quote!([#(#row),*]));
    let p = &ids[9..12];
    quote!(::planar_arm::__private::isometry3([#(#r),*], [#(#p),*]))
}

/// The docs of `mass_matrix` (`mass`) or `coriolis`: the formulas where they were multiplied
/// out and fit ([`formula_doc`]), else where to find them.
fn dynamics_doc(title: &str, d: &SpatialDerived, mass: bool) -> String {
    let Some(dynamics) = &d.dynamics else {
        return format!(
            "{title}\n\nNot multiplied out for this arm: a link's velocities would exceed \
             {DYNAMICS_BUDGET} terms, and the products that M and c need would cost its build \
             more than they are worth (`EXACT` has its tool pose, V and g where those fit). \
             `#[arm(exact_dynamics)]` on the struct multiplies them out for `EXACT` and these \
             docs whatever their size, as does \
             `planar_arm::symbolic::spatial::lagrangian::expand_dynamics` (feature `symbolic`) \
             for any budget."
        );
    };
    let rows: Vec<(String, &Expr<Poly>)> = if mass {
        let n = dynamics.mass_matrix.len();
        (0..n)
            .flat_map(|i| (i..n).map(move |j| (i, j)))
            .map(|(i, j)| (format!("M{}{}", i + 1, j + 1), &dynamics.mass_matrix[i][j]))
            .collect()
    } else {
        dynamics
            .coriolis
            .iter()
            .enumerate()
            .map(|(i, e)| (format!("c{}", i + 1), e))
            .collect()
    };
    formula_doc(
        &format!("{title} Multiplied out from the kinetic energy (also in `EXACT`):"),
        &rows,
    )
}

/// A method's documentation when its formulas were not multiplied out.
fn unexpanded_doc(title: &str) -> String {
    format!(
        "{title}\n\nEvaluated as the product of the joints' transformations: multiplied out, \
         this arm's formulas would exceed {EXPANSION_BUDGET} terms."
    )
}

/// `const EXACT`: the tool pose's entries, V and g, if they were multiplied out.
fn exact(n: usize, d: &SpatialDerived) -> Result<TokenStream, EmitError> {
    let n = Literal::usize_unsuffixed(n);
    let Some(k) = &d.kinematics else {
        return Ok(quote! {
            const EXACT: ::planar_arm::exact::SpatialDerivation<#n> =
                ::planar_arm::exact::SpatialDerivation { expansion: ::core::option::Option::None };
        });
    };
    let mut names = Vec::new();
    let mut terms = |e: &Expr<Poly>| -> Result<TokenStream, EmitError> {
        let code = Literal::byte_string(&crate::compact::encode(e, &mut names)?);
        let table = local("NAMES");
        Ok(quote!(::planar_arm::__private::terms(#code, #table)))
    };
    let mut rows = Vec::new();
    for i in 0..3 {
        let mut row = Vec::new();
        for j in 0..3 {
            row.push(terms(&k.tool.r[i][j])?);
        }
        row.push(terms(&k.tool.p[i])?);
        rows.push(quote!([#(#row),*]));
    }
    let v = terms(&k.potential_energy)?;
    let g = k
        .gravity
        .iter()
        .map(&mut terms)
        .collect::<Result<Vec<_>, _>>()?;
    // M and c are long; a coefficient that does not fit the i128 of `EXACT` leaves them out
    // rather than failing the derive.
    let (mass_matrix, coriolis) = match &d.dynamics {
        Some(dynamics) => {
            let mut extra = names.clone();
            let mut terms = |e: &Expr<Poly>| -> Result<TokenStream, EmitError> {
                let code = Literal::byte_string(&crate::compact::encode(e, &mut extra)?);
                let table = local("NAMES");
                Ok(quote!(::planar_arm::__private::terms(#code, #table)))
            };
            let rows: Result<Vec<TokenStream>, EmitError> = dynamics
                .mass_matrix
                .iter()
                .map(|row| {
                    let row = row.iter().map(&mut terms).collect::<Result<Vec<_>, _>>()?;
                    Ok(quote!([#(#row),*]))
                })
                .collect();
            let c: Result<Vec<TokenStream>, EmitError> =
                dynamics.coriolis.iter().map(&mut terms).collect();
            match (rows, c) {
                (Ok(rows), Ok(c)) => {
                    names = extra;
                    (
                        quote!(::core::option::Option::Some([#(#rows),*])),
                        quote!(::core::option::Option::Some([#(#c),*])),
                    )
                }
                _ => (
                    quote!(::core::option::Option::None),
                    quote!(::core::option::Option::None),
                ),
            }
        }
        None => (
            quote!(::core::option::Option::None),
            quote!(::core::option::Option::None),
        ),
    };
    let table = local("NAMES");
    let names = names.iter().map(|n| n.trim_start_matches("r#"));
    Ok(quote! {
        const EXACT: ::planar_arm::exact::SpatialDerivation<#n> = {
            const #table: &[&#STR] = &[#(#names),*];
            ::planar_arm::exact::SpatialDerivation {
                expansion: ::core::option::Option::Some(::planar_arm::exact::SpatialExpansion {
                    tip: [#(#rows),*],
                    potential_energy: #v,
                    gravity: [#(#g),*],
                    mass_matrix: #mass_matrix,
                    coriolis: #coriolis,
                }),
            }
        };
    })
}

fn angle_tokens(a: &FixedAngle) -> Result<TokenStream, EmitError> {
    crate::emit::f64_value_tokens(a.value())
}

fn triple(v: &[Poly; 3]) -> Result<TokenStream, EmitError> {
    let [x, y, z] = [
        coefficient_tokens(&v[0])?,
        coefficient_tokens(&v[1])?,
        coefficient_tokens(&v[2])?,
    ];
    Ok(quote!(::planar_arm::nalgebra::Vector3::new(#x, #y, #z)))
}

/// `fn model()`: the numeric description, run-time parameters read from `self`.
fn model(arm: &SpatialArmSpec) -> Result<TokenStream, EmitError> {
    let n = Literal::usize_unsuffixed(arm.joints.len());
    let mut joints = Vec::new();
    let mut links = Vec::new();
    for j in &arm.joints {
        let geometry = match &j.geometry {
            SpatialGeometry::Dh { a, alpha, d, theta }
            | SpatialGeometry::Mdh { a, alpha, d, theta } => {
                let variant = if matches!(j.geometry, SpatialGeometry::Dh { .. }) {
                    quote!(Dh)
                } else {
                    quote!(Mdh)
                };
                let (a, d) = (coefficient_tokens(a)?, coefficient_tokens(d)?);
                let (alpha, theta) = (angle_tokens(alpha)?, angle_tokens(theta)?);
                quote!(::planar_arm::spatial::JointGeometry::#variant { a: #a, alpha: #alpha, d: #d, theta: #theta })
            }
            SpatialGeometry::Urdf { xyz, rpy, axis } => {
                let xyz = triple(xyz)?;
                let [r, p, y] = [
                    angle_tokens(&rpy[0])?,
                    angle_tokens(&rpy[1])?,
                    angle_tokens(&rpy[2])?,
                ];
                let axis = triple(axis)?;
                quote!(::planar_arm::spatial::JointGeometry::Urdf {
                    xyz: #xyz,
                    rpy: ::planar_arm::nalgebra::Vector3::new(#r, #p, #y),
                    axis: #axis,
                })
            }
        };
        let kind = match j.kind {
            JointKind::Revolute => quote!(::planar_arm::Joint::Revolute),
            JointKind::Prismatic => quote!(::planar_arm::Joint::Prismatic),
        };
        let range = match &j.range {
            Some((lo, hi)) => {
                let (lo, hi) = (f64_tokens(lo)?, f64_tokens(hi)?);
                quote!(::core::option::Option::Some((#lo, #hi)))
            }
            None => quote!(::core::option::Option::None),
        };
        let (armature, damping, frictionloss, stiffness, springref) = (
            coefficient_tokens(&j.armature)?,
            coefficient_tokens(&j.damping)?,
            coefficient_tokens(&j.frictionloss)?,
            coefficient_tokens(&j.stiffness)?,
            coefficient_tokens(&j.springref)?,
        );
        joints.push(quote!(::planar_arm::spatial::SpatialJoint {
            geometry: #geometry,
            kind: #kind,
            range: #range,
            armature: #armature,
            damping: #damping,
            frictionloss: #frictionloss,
            stiffness: #stiffness,
            springref: #springref,
        }));
        links.push(link_tokens(&SpatialBody::of_link(j))?);
    }
    let payload = match &arm.payload {
        Some(body) => {
            let link = link_tokens(body)?;
            quote!(::core::option::Option::Some(#link))
        }
        None => quote!(::core::option::Option::None),
    };
    let gravity = triple(&arm.gravity)?;
    let tool_xyz = triple(&arm.tool_xyz)?;
    let [r, p, y] = [
        angle_tokens(&arm.tool_rpy[0])?,
        angle_tokens(&arm.tool_rpy[1])?,
        angle_tokens(&arm.tool_rpy[2])?,
    ];
    Ok(quote! {
        #[inline]
        fn model(&self) -> ::planar_arm::spatial::SpatialModel<#n> {
            ::planar_arm::spatial::SpatialModel {
                joints: [#(#joints),*],
                links: [#(#links),*],
                gravity: #gravity,
                tool: ::planar_arm::nalgebra::Isometry3::from_parts(
                    ::planar_arm::nalgebra::Translation3::from(#tool_xyz),
                    ::planar_arm::nalgebra::UnitQuaternion::from_euler_angles(#r, #p, #y),
                ),
                payload: #payload,
            }
        }
    })
}

/// A body as a `SpatialLink`.
fn link_tokens(body: &SpatialBody) -> Result<TokenStream, EmitError> {
    let mass = coefficient_tokens(&body.mass)?;
    let com = triple(&body.com)?;
    let i = body
        .inertia
        .iter()
        .map(coefficient_tokens)
        .collect::<Result<Vec<_>, _>>()?;
    let (xx, yy, zz, xy, xz, yz) = (&i[0], &i[1], &i[2], &i[3], &i[4], &i[5]);
    Ok(quote!(::planar_arm::spatial::SpatialLink {
        mass: #mass,
        com: #com,
        inertia: ::planar_arm::nalgebra::Matrix3::new(#xx, #xy, #xz, #xy, #yy, #yz, #xz, #yz, #zz),
    }))
}

/// `fn inverse_kinematics`: the closed form the geometry allows, decided here for arms whose
/// values are known; at run time from `model()` for arms with run-time lengths; otherwise
/// `NoClosedForm`.
fn inverse_kinematics(arm: &SpatialArmSpec) -> Result<TokenStream, EmitError> {
    let n = arm.joints.len();
    let nn = Literal::usize_unsuffixed(n);
    let target = local("target");
    let ranges = arm
        .joints
        .iter()
        .map(|j| match &j.range {
            Some((lo, hi)) => {
                let (lo, hi) = (f64_tokens(lo)?, f64_tokens(hi)?);
                Ok(quote!(::core::option::Option::Some((#lo, #hi))))
            }
            None => Ok(quote!(::core::option::Option::None)),
        })
        .collect::<Result<Vec<_>, EmitError>>()?;
    let sig = quote!(fn inverse_kinematics(&self, #target: &::planar_arm::nalgebra::Isometry3<#F64>)
        -> ::core::result::Result<::planar_arm::spatial::IkSolutions<#nn>, ::planar_arm::ArmError>);
    let none = |what: &str| {
        quote! {
            /// No closed form for this arm's geometry: see `SpatialIk` for the classes that
            /// have one, and `inverse_kinematics_near` for any arm.
            #[inline]
            #sig {
                let _ = #target;
                ::core::result::Result::Err(::planar_arm::ArmError::NoClosedForm { what: #what })
            }
        }
    };
    if n != 6 {
        return Ok(none(
            "closed-form inverse kinematics needs six joints; use inverse_kinematics_near",
        ));
    }
    if let Some(g) = decouple(arm) {
        let class = match g.class {
            Decoupling::SphericalWrist => quote!(SphericalWrist),
            Decoupling::SlidingWrist => quote!(SlidingWrist),
            Decoupling::ParallelTriple => quote!(ParallelTriple),
        };
        let v3 = |v: &[f64; 3]| -> Result<TokenStream, EmitError> {
            let [x, y, z] = [
                crate::emit::f64_value_tokens(v[0])?,
                crate::emit::f64_value_tokens(v[1])?,
                crate::emit::f64_value_tokens(v[2])?,
            ];
            Ok(quote!(::planar_arm::nalgebra::Vector3::new(#x, #y, #z)))
        };
        let points = g.points.iter().map(v3).collect::<Result<Vec<_>, _>>()?;
        let axes = g.axes.iter().map(v3).collect::<Result<Vec<_>, _>>()?;
        let (r, p) = &g.home;
        let rows = r
            .iter()
            .map(|row| {
                let row = row
                    .iter()
                    .map(|x| crate::emit::f64_value_tokens(*x))
                    .collect::<Result<Vec<_>, _>>()?;
                Ok(quote!([#(#row),*]))
            })
            .collect::<Result<Vec<_>, EmitError>>()?;
        let p = p
            .iter()
            .map(|x| crate::emit::f64_value_tokens(*x))
            .collect::<Result<Vec<_>, _>>()?;
        let centre = v3(&g.centre)?;
        let scale = crate::emit::f64_value_tokens(g.scale)?;
        let doc = format!(
            "Every solution in closed form ({}: decided at compile time from the exact geometry); \
             see `planar_arm::spatial::SpatialIk`.",
            match g.class {
                Decoupling::SphericalWrist => "a spherical wrist, axes 2 and 3 parallel",
                Decoupling::SlidingWrist => "a spherical wrist, a sliding third joint",
                Decoupling::ParallelTriple => "axes 2, 3 and 4 parallel, axes 5 and 6 meeting",
            }
        );
        return Ok(quote! {
            #[doc = #doc]
            #[inline]
            #sig {
                let ik = ::planar_arm::spatial::SpatialIk {
                    class: ::planar_arm::spatial::IkClass::#class,
                    points: [#(#points),*],
                    axes: [#(#axes),*],
                    home: ::planar_arm::__private::isometry3([#(#rows),*], [#(#p),*]),
                    centre: #centre,
                    scale: #scale,
                };
                ik.solve(#target, &[#(#ranges),*])
            }
        });
    }
    let literal = arm.joints.iter().all(|j| {
        matches!(&j.geometry, SpatialGeometry::Dh { a, d, .. } | SpatialGeometry::Mdh { a, d, .. }
            if a.params().iter().all(|p| p.value().is_some()) && d.params().iter().all(|p| p.value().is_some()))
            || matches!(&j.geometry, SpatialGeometry::Urdf { xyz, .. } if xyz.iter().all(|c| c.params().iter().all(|p| p.value().is_some())))
    });
    if literal {
        return Ok(none(
            "this arm's axes are not of a closed-form class; use inverse_kinematics_near",
        ));
    }
    Ok(quote! {
        /// Every solution in closed form, the class decided at run time from `model()` (the
        /// arm's lengths are run-time parameters); `NoClosedForm` if the geometry has none.
        #[inline]
        #sig {
            match ::planar_arm::spatial::SpatialIk::of_model(&self.model()) {
                ::core::option::Option::Some(ik) => ik.solve(#target, &[#(#ranges),*]),
                ::core::option::Option::None => ::core::result::Result::Err(::planar_arm::ArmError::NoClosedForm {
                    what: "this arm's axes, with the lengths it has now, are not of a closed-form class; use inverse_kinematics_near",
                }),
            }
        }
    })
}
