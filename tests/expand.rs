//! Expansion snapshots (zerocopy-derive style): the code generated for the paper's two- and
//! three-link arms, pretty-printed with prettyplease and compared with the checked-in files in
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
            gravity: ratio(981, 100),
            payload: None,
        }
    } else {
        let mut arm = ArmSpec::paper(n);
        arm.gravity = ratio(981, 100);
        arm
    };
    let derived = Derived::new(&arm);
    let names: &[&str] = if n == 0 {
        &["turret", "boom"]
    } else {
        &["upper", "fore", "hand"]
    };
    let header = Header {
        impl_generics: quote!(),
        ty: match n {
            0 => quote!(Polar),
            2 => quote!(Paper2),
            _ => quote!(Paper3),
        },
        where_clause: quote!(),
        fields: names[..arm.links.len()]
            .iter()
            .map(|s| Ident::new(s, Span::call_site()))
            .collect(),
    };
    let mut tokens = generate(&derived, &header).expect("the paper's arms emit");
    tokens.extend(closed_forms(&derived, &header));
    // Not rewritten by `paths::qualify`, as the derive's output is not without a crate path:
    // the engine writes the primitives' `::core` paths itself.
    let file: syn::File = syn::parse2(tokens).expect("generated code parses");
    prettyplease::unparse(&file)
}

fn snapshot(name: &str, n: usize) {
    let actual = expand(n);
    assert_eq!(actual, expand(n), "generation is not deterministic");
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
