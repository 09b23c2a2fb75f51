//! The kinematics' and statics' methods: the tip pose, the Jacobian, the joints' positions,
//! the tip in polar form and the joint torques of a tip load.

use quote::quote;

use super::{Context, Table};
use crate::emission::function::{matrix, vector, Fn, Param};
use crate::emit::formula_doc;
use crate::methods::Derived;
use crate::paths::F64;
use crate::slp::Emit;

/// Pushes the kinematics' and statics' methods.
pub(super) fn methods<'a, C: Emit>(d: &'a Derived<C>, cx: &Context, table: &mut Table<'a>) {
    let (n, nn, ki) = (cx.n, &cx.nn, &d.kinematics);
    let (tx, ty) = &ki.points[n];
    let methods = &mut table.programs;
    methods.push(
        Fn::new(
            "tip_pose",
            vec![cx.q],
            quote!(::planar_arm::nalgebra::Isometry2<#F64>),
            formula_doc(
                &format!(
                    "The tip pose; the orientation is the last link's angle {}.",
                    ki.tip_angle
                ),
                &[("x".into(), tx), ("y".into(), ty)],
            ),
            d.tip_pose_method(),
            Box::new(|ids| {
                let (x, y, c, s) = (&ids[0], &ids[1], &ids[2], &ids[3]);
                quote!(::planar_arm::__private::pose(#x, #y, #c, #s))
            }),
        )
        .in_f64(),
    );
    let mut j_rows = Vec::new();
    for (r, row) in ki.jacobian.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            j_rows.push((format!("J{}{}", r + 1, j + 1), e));
        }
    }
    methods.push(Fn::new(
        "jacobian",
        vec![cx.q],
        quote!(::planar_arm::nalgebra::SMatrix<__T, 3, #nn>),
        formula_doc("The Jacobian d(x, y, phi)/dq.", &j_rows),
        d.jacobian_method(),
        Box::new(move |ids| matrix(3, n, ids)),
    ));
    methods.push(Fn::new(
        "joint_positions",
        vec![cx.q],
        quote!([::planar_arm::nalgebra::Point2<__T>; #nn]),
        "The position of each joint, joint 1 at the origin.".to_string(),
        d.joint_positions_method(),
        Box::new(|ids| {
            let pts = ids.chunks(2).map(|p| {
                let (x, y) = (&p[0], &p[1]);
                quote!(::planar_arm::nalgebra::Point2::new(#x, #y))
            });
            quote!([#(#pts),*])
        }),
    ));
    methods.push(
        Fn::new(
            "tip_polar",
            vec![cx.q],
            quote!((#F64, #F64)),
            formula_doc(
                "The tip in polar form: r from r^2 (which does not depend on q1), theta = atan2(y, x).",
                &[("r^2".into(), &ki.radius_squared)],
            ),
            d.tip_polar_method(),
            Box::new(|ids| {
                let (r2, x, y) = (&ids[0], &ids[1], &ids[2]);
                quote!(::planar_arm::__private::polar(#r2, #x, #y))
            }),
        )
        .in_f64(),
    );
    methods.push(
        Fn::new(
            "joint_torques",
            vec![cx.q, Param::Force, Param::Torque],
            quote!(::planar_arm::nalgebra::SVector<#F64, #nn>),
            "Statics: tau = J^T (u, v, torque), the motor torques that make the tip exert force (u, v) and torque `torque`.".to_string(),
            d.joint_torques_method(),
            Box::new(vector),
        )
        .in_f64(),
    );
}
