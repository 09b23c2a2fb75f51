//! Expansion snapshots (zerocopy-derive style): the code generated for the paper's two- and
//! three-link arms, pretty-printed with prettyplease and compared with the checked-in files in
//! `tests/expand/`. A change to the emitted code shows up here as a readable diff; re-bless on
//! purpose only, with `PLANAR_ARM_BLESS=1 cargo test --test expand`.
//!
//! The same input must give byte-identical output, so each arm is also generated twice.

use planar_arm::symbolic::generate::{closed_forms, generate, Header};
use planar_arm::symbolic::methods::Derived;
use planar_arm::symbolic::ring::ratio;
use planar_arm::symbolic::ArmSpec;
use proc_macro2::{Ident, Span};
use quote::quote;

fn expand(n: usize) -> String {
    let mut arm = ArmSpec::paper(n);
    arm.gravity = ratio(981, 100);
    let derived = Derived::new(&arm);
    let names = ["upper", "fore", "hand"];
    let header = Header {
        impl_generics: quote!(),
        ty: if n == 2 {
            quote!(Paper2)
        } else {
            quote!(Paper3)
        },
        where_clause: quote!(),
        fields: names[..n]
            .iter()
            .map(|s| Ident::new(s, Span::call_site()))
            .collect(),
    };
    let mut tokens = generate(&derived, &header).expect("the paper's arms emit");
    tokens.extend(closed_forms(&derived, &header));
    // As the derive finishes its output: primitives by their `::core` paths.
    let tokens = planar_arm::symbolic::paths::qualify(tokens, None);
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
