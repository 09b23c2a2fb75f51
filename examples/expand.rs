//! Prints the code `#[derive(PlanarArm)]` generates for an arm, pretty-printed, for readers
//! without `cargo expand`. The arm is built through the engine's API, exactly as the derive
//! builds it from the attributes.
//!
//! ```text
//! cargo run --example expand            # the paper's two equal links
//! cargo run --example expand -- 3       # three equal links
//! ```

use planar_arm::symbolic::generate::{closed_forms, generate, Header};
use planar_arm::symbolic::methods::Derived;
use planar_arm::symbolic::ring::{int, ratio};
use planar_arm::symbolic::ArmSpec;
use quote::quote;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let n: usize = std::env::args().nth(1).map_or(Ok(2), |s| s.parse())?;
    let mut arm = ArmSpec::paper(n);
    arm.gravity = ratio(981, 100);
    let _ = int(1);
    let derived = Derived::new(&arm);
    let header = Header {
        impl_generics: quote!(),
        ty: quote!(PaperArm),
        where_clause: quote!(),
        fields: Vec::new(),
    };
    let mut tokens = generate(&derived, &header)?;
    tokens.extend(closed_forms(&derived, &header));
    let file: syn::File = syn::parse2(tokens)?;
    println!("{}", prettyplease::unparse(&file));
    Ok(())
}
