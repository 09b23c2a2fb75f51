//! Prints the code `#[derive(PlanarArm)]` (or `#[derive(SpatialArm)]`) generates, pretty-printed, for readers without
//! `cargo expand`: for the paper's arms, or for every derived arm in a file of yours.
//!
//! ```text
//! cargo run --example expand                          # the paper's two equal links
//! cargo run --example expand -- 3                     # three equal links
//! cargo run --example expand -- path/to/arm.rs        # each #[derive(PlanarArm)] in the file
//! cargo run --example expand -- path/to/arm.rs Scara  # one of them
//! ```
//!
//! The output is the derive's own: this example compiles the derive's parsing, checking and
//! expansion (`derive/src/`) into itself and runs them on the parsed file, so an error in the
//! attributes prints the message the compiler would show.

// The derive's modules, as they are; the proc-macro entry point (`derive/src/lib.rs`) is the
// only part left out, since a proc-macro crate cannot be linked into a program.
#[path = "../derive/src/ast.rs"]
mod ast;
#[path = "../derive/src/attr.rs"]
mod attr;
#[path = "../derive/src/check.rs"]
mod check;
#[path = "../derive/src/ctxt.rs"]
mod ctxt;
#[path = "../derive/src/expand.rs"]
mod expand;
#[path = "../derive/src/models/mod.rs"]
mod models;
#[path = "../derive/src/spatial/mod.rs"]
mod spatial;
#[path = "../derive/src/value.rs"]
mod value;

use std::process::ExitCode;

/// The paper's arm of `n` equal unit rods as a user would write it.
fn paper(n: usize) -> String {
    let names = ["upper", "fore", "hand", "finger"];
    let links: String = (0..n)
        .map(|i| {
            let name = names
                .get(i)
                .map_or_else(|| format!("link{}", i + 1), |s| (*s).to_string());
            format!("    #[arm(length = 1, mass = 1)]\n    {name}: Revolute,\n")
        })
        .collect();
    format!("#[derive(PlanarArm)]\n#[arm(gravity = 9.81)]\nstruct Paper{n} {{\n{links}}}\n")
}

/// Which of the two derives the struct asks for, if any.
fn derives(attrs: &[syn::Attribute]) -> Option<&'static str> {
    ["PlanarArm", "SpatialArm"]
        .into_iter()
        .find(|name| derives_named(attrs, name))
}

fn derives_named(attrs: &[syn::Attribute], name: &str) -> bool {
    attrs
        .iter()
        .filter(|a| a.path().is_ident("derive"))
        .any(|a| {
            a.parse_args_with(
                syn::punctuated::Punctuated::<syn::Path, syn::Token![,]>::parse_terminated,
            )
            .is_ok_and(|paths| {
                paths
                    .iter()
                    .any(|p| p.segments.last().is_some_and(|s| s.ident == name))
            })
        })
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let (source, wanted) = match args.first() {
        None => (paper(2), None),
        Some(n) if n.parse::<usize>().is_ok_and(|n| (1..=4).contains(&n)) => {
            (paper(n.parse().unwrap_or(2)), None)
        }
        Some(path) => match std::fs::read_to_string(path) {
            Ok(text) => (text, args.get(1).cloned()),
            Err(e) => {
                eprintln!("error: cannot read {path}: {e} (give a file, or 1 to 4 links)");
                return ExitCode::FAILURE;
            }
        },
    };
    let file = match syn::parse_file(&source) {
        Ok(file) => file,
        Err(e) => {
            eprintln!("error: the file does not parse as Rust: {e}");
            return ExitCode::FAILURE;
        }
    };
    let mut found = 0;
    let mut failed = false;
    for item in file.items {
        let syn::Item::Struct(s) = item else { continue };
        let Some(derive) = derives(&s.attrs) else {
            continue;
        };
        if wanted.as_ref().is_some_and(|w| s.ident != w) {
            continue;
        }
        found += 1;
        let input: syn::DeriveInput = s.into();
        let tokens = if derive == "SpatialArm" {
            spatial::expand::derive(&input)
        } else {
            expand::derive(&input)
        };
        let text = tokens.to_string();
        if text.contains("compile_error") {
            // Only the errors matter then; the stub that follows them is not the arm.
            failed = true;
            for message in text.split("compile_error !").skip(1) {
                let message = message.split('"').nth(1).unwrap_or(message);
                eprintln!("error in `{}`: {message}", input.ident);
            }
            continue;
        }
        match syn::parse2::<syn::File>(tokens) {
            Ok(out) => println!("{}", prettyplease::unparse(&out)),
            Err(e) => {
                eprintln!("error: the generated code does not parse: {e}");
                failed = true;
            }
        }
    }
    if found == 0 {
        eprintln!(
            "error: no struct with #[derive(PlanarArm)] or #[derive(SpatialArm)]{} in the input",
            wanted.map_or_else(String::new, |w| format!(" named `{w}`"))
        );
        return ExitCode::FAILURE;
    }
    if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}
