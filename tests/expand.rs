//! Expansion snapshots (zerocopy-derive style): the code generated for the paper's two- and
//! three-link arms, the polar arm and the PUMA 560 (`#[derive(SpatialArm)]`), pretty-printed with prettyplease and compared with the checked-in files in
//! `tests/expand/`. A change to the emitted code shows up here as a readable diff; re-bless on
//! purpose only, with `PLANAR_ARM_BLESS=1 cargo test --test expand`.
//!
//! The same input must give byte-identical output, so each arm is also generated twice.

use planar_arm::symbolic::generate::{closed_forms, generate, Header};
use planar_arm::symbolic::methods::Derived;
use planar_arm::symbolic::ring::{int, ratio};
use planar_arm::symbolic::{ArmSpec, JointKind, LinkSpec};
use proc_macro2::{Ident, Span};
use quote::quote;

/// The paper's equal rods (two or three), or with `n = 0` the polar arm: a turret and a
/// prismatic boom with a range.
fn expand(n: usize) -> String {
    let arm = if n == 0 {
        ArmSpec {
            links: vec![
                LinkSpec::rod(ratio(1, 5), int(3)),
                LinkSpec {
                    joint: JointKind::Prismatic,
                    range: Some((int(0), ratio(3, 5))),
                    ..LinkSpec::rod(ratio(1, 2), ratio(3, 2))
                },
            ],
            gravity: planar_arm_core::down(ratio(981, 100)),
            payload: None,
        }
    } else {
        let mut arm = ArmSpec::paper(n);
        arm.gravity = planar_arm_core::down(ratio(981, 100));
        arm
    };
    let derived = Derived::new(&arm);
    let names: &[&str] = if n == 0 {
        &["turret", "boom"]
    } else {
        &["upper", "fore", "hand"]
    };
    let header = Header::new(
        quote!(),
        match n {
            0 => quote!(Polar),
            2 => quote!(Paper2),
            _ => quote!(Paper3),
        },
        quote!(),
        names[..arm.links.len()]
            .iter()
            .map(|s| Ident::new(s, Span::call_site()))
            .collect(),
    );
    let mut tokens = generate(&derived, &header).expect("the paper's arms emit");
    tokens.extend(closed_forms(&derived, &header));
    // Not rewritten by `paths::qualify`, as the derive's output is not without a crate path:
    // the engine writes the primitives' `::core` paths itself.
    let file: syn::File = syn::parse2(tokens).expect("generated code parses");
    prettyplease::unparse(&file)
}

/// The PUMA 560 of `examples/puma.rs` (geometry and masses; no inertia, which the kinematics
/// and gravity do not read), through the spatial engine and emission.
fn expand_puma() -> String {
    use planar_arm::symbolic::ring::parse_decimal;
    use planar_arm::symbolic::spatial::{
        generate_spatial, FixedAngle, SpatialArmSpec, SpatialGeometry, SpatialJointSpec,
    };
    use planar_arm::symbolic::Poly;
    let number = |s: &str| {
        Poly::constant(parse_decimal(s.trim_start_matches('-')).map_or_else(
            || unreachable!("{s}"),
            |r| if s.starts_with('-') { -r } else { r },
        ))
    };
    let joint = |a: &str, alpha: i64, d: &str, mass: &str, com: [&str; 3]| SpatialJointSpec {
        geometry: SpatialGeometry::Dh {
            a: number(a),
            alpha: FixedAngle::pi(ratio(alpha, 2)),
            d: number(d),
            theta: FixedAngle::zero(),
        },
        kind: JointKind::Revolute,
        mass: number(mass),
        com: com.map(number),
        inertia: core::array::from_fn(|_| Poly::default()),
        range: None,
        armature: Poly::default(),
        damping: Poly::default(),
        frictionloss: Poly::default(),
        stiffness: Poly::default(),
        springref: Poly::default(),
    };
    let arm = SpatialArmSpec {
        joints: vec![
            joint("0", 1, "0", "0", ["0", "0", "0"]),
            joint("0.4318", 0, "0", "17.4", ["-0.3638", "0.006", "0.2275"]),
            joint(
                "0.0203",
                -1,
                "0.15005",
                "4.8",
                ["-0.0203", "-0.0141", "0.07"],
            ),
            joint("0", 1, "0.4318", "0.82", ["0", "0.019", "0"]),
            joint("0", -1, "0", "0.34", ["0", "0", "0"]),
            joint("0", 0, "0", "0.09", ["0", "0", "0.032"]),
        ],
        gravity: [
            Poly::default(),
            Poly::default(),
            Poly::constant(ratio(-981, 100)),
        ],
        tool_xyz: core::array::from_fn(|_| Poly::default()),
        tool_rpy: core::array::from_fn(|_| FixedAngle::zero()),
        payload: None,
    };
    let header = Header::new(
        quote!(),
        quote!(Puma560),
        quote!(),
        ["waist", "shoulder", "elbow", "wrist1", "wrist2", "wrist3"]
            .iter()
            .map(|s| Ident::new(s, Span::call_site()))
            .collect(),
    );
    let tokens = generate_spatial(&arm, &header).expect("the PUMA emits");
    let file: syn::File = syn::parse2(tokens).expect("generated code parses");
    prettyplease::unparse(&file)
}

fn snapshot(name: &str, n: usize) {
    let make = || if n == 6 { expand_puma() } else { expand(n) };
    let actual = make();
    assert_eq!(actual, make(), "generation is not deterministic");
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/expand")
        .join(name);
    if std::env::var_os("PLANAR_ARM_BLESS").is_some() {
        std::fs::write(&path, &actual).expect("write snapshot");
        return;
    }
    let expected =
        std::fs::read_to_string(&path).expect("snapshot exists; bless with PLANAR_ARM_BLESS=1");
    if actual != expected {
        let first = actual
            .lines()
            .zip(expected.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(0);
        panic!(
            "{name} changed at line {}:\n  expected: {}\n  actual:   {}\nre-bless on purpose with PLANAR_ARM_BLESS=1",
            first + 1,
            expected.lines().nth(first).unwrap_or(""),
            actual.lines().nth(first).unwrap_or("")
        );
    }
}

#[test]
fn paper_two_links() {
    snapshot("paper2.rs", 2);
}

#[test]
fn paper_three_links() {
    snapshot("paper3.rs", 3);
}

#[test]
fn polar_arm() {
    snapshot("polar.rs", 0);
}

#[test]
fn spatial_puma() {
    snapshot("puma.rs", 6);
}
