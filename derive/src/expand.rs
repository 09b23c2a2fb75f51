//! Expansion: a valid arm goes to the engine; an invalid one gets its errors and a stub impl.

use num_traits::Signed;
use proc_macro2::TokenStream;
use quote::{quote, ToTokens};
use syn::DeriveInput;

use planar_arm_core::emit::EmitError;
use planar_arm_core::generate::{generate, Header};
use planar_arm_core::methods::Derived;
use planar_arm_core::paths::F64;
use planar_arm_core::ring::{to_i128_pair, Rational};
use planar_arm_core::slp::Emit;
use planar_arm_core::{ArmSpec, Expr, JointKind, Poly};

use crate::ast::Arm;
use crate::check::check;
use crate::ctxt::Ctxt;

pub fn derive(input: &DeriveInput) -> TokenStream {
    let tokens = match try_derive(input) {
        Ok(tokens) => tokens,
        Err(errors) => {
            let fallback = fallback(input);
            quote!(#errors #fallback)
        }
    };
    // The engine writes primitives by their `::core` paths (the test below checks every
    // form), so only a renamed crate needs the rewrite, which walks every token: through the
    // compiler's bridge that walk was a quarter of the expansion of a 6-link arm.
    match krate(input) {
        Some(path) => planar_arm_core::paths::qualify(tokens, Some(&path)),
        None => tokens,
    }
}

/// The path of `planar_arm` when it is not `::planar_arm`: given by `#[arm(crate = "...")]`
/// (errors in it are reported by the full parse), or else the name the user crate's
/// Cargo.toml gives the dependency (`arm = { package = "planar_arm" }`).
pub(crate) fn krate(input: &DeriveInput) -> Option<TokenStream> {
    let cx = Ctxt::new();
    let path = crate::attr::parse(&cx, &input.attrs, crate::attr::Place::Struct)
        .and_then(|a| a.krate)
        .map(|p| p.to_token_stream());
    // Reported again, with the rest, by `try_derive`.
    let _ = cx.check();
    path.or_else(renamed)
}

/// `::name` when the crate being compiled depends on `planar_arm` under another name. The
/// package itself (its tests and examples) and a manifest that cannot be read keep the default.
fn renamed() -> Option<TokenStream> {
    match proc_macro_crate::crate_name("planar_arm") {
        Ok(proc_macro_crate::FoundCrate::Name(name)) if name != "planar_arm" => {
            let ident = syn::Ident::new(&name, proc_macro2::Span::call_site());
            Some(quote!(::#ident))
        }
        _ => None,
    }
}

pub(crate) fn header(input: &DeriveInput) -> Header {
    let (impl_generics, ty_generics, where_clause) = input.generics.split_for_impl();
    let ident = &input.ident;
    Header::new(
        impl_generics.to_token_stream(),
        quote!(#ident #ty_generics),
        where_clause.to_token_stream(),
        field_names(input),
    )
}

fn try_derive(input: &DeriveInput) -> Result<TokenStream, TokenStream> {
    let cx = Ctxt::new();
    let arm = Arm::from_ast(&cx, input);
    let from_file = arm.as_ref().is_some_and(|a| {
        a.attrs.mentioned.contains(&crate::attr::URDF)
            || a.attrs.mentioned.contains(&crate::attr::MJCF)
    });
    let (spec, file) = if from_file {
        match arm
            .as_ref()
            .and_then(|arm| crate::check::check_file(&cx, arm))
        {
            Some((spec, file)) => (Some(spec), Some(file)),
            None => (None, None),
        }
    } else {
        (arm.as_ref().and_then(|arm| check(&cx, arm)), None)
    };
    cx.check()?;
    let (Some(arm), Some(spec)) = (arm, spec) else {
        // Unreachable: `check` reports every reason it returns `None`.
        return Err(syn::Error::new_spanned(&input.ident, "invalid arm").to_compile_error());
    };
    let mut header = header(input);
    let mut depend = TokenStream::new();
    if let (Some(file), Some((_, lit))) = (&file, &arm.attrs.model) {
        header.joint_names.clone_from(&file.names);
        let mut doc = vec![format!(
            "The joints' names in `{}`, base first: the order of `q`.",
            lit.value()
        )];
        doc.extend(file.planar.notes.iter().cloned());
        header.joint_names_doc = doc.join("\n\n");
        // `include_bytes!` makes cargo rebuild the user's crate when the file changes.
        let path = file.path.display().to_string();
        depend = quote!(
            const _: &[u8] = ::core::include_bytes!(#path);
        );
    }
    let header = header;
    let first = derive_spec(&arm, &spec, &header).map(|mut t| {
        t.extend(depend.clone());
        t
    });
    if first.is_ok() {
        return first;
    }
    // Exact coefficients too long for the `i128` of `EXACT`: the literals with the most digits
    // enter as named constants instead (exact in that symbol, as a run-time parameter whose
    // value is fixed; the generated code uses their `f64`), fewer digits each round.
    for bits in NAMED_BITS {
        let (named, count) = name_long_literals(&spec, bits);
        if count > 0 {
            if let Ok(mut tokens) = derive_spec(&arm, &named, &header) {
                tokens.extend(depend);
                return Ok(tokens);
            }
        }
    }
    first
}

/// The sizes (bits of the larger of numerator and denominator) above which literals become
/// named constants, tried in turn: URDF's and MuJoCo's 17-digit decimals are about 60 bits.
pub(crate) const NAMED_BITS: [u64; 3] = [48, 32, 20];

/// `spec` with every literal value of more than `bits` bits a named constant called by its
/// shortest decimal (`0.000039175660390264734`), and how many there were.
fn name_long_literals(spec: &ArmSpec<Poly>, bits: u64) -> (ArmSpec<Poly>, usize) {
    let mut count = 0;
    let named = spec.map(|p| {
        let q = named_if_long(p, bits);
        count += usize::from(q != *p);
        q
    });
    (named, count)
}

/// `p` as a named constant if it is a literal of more than `bits` bits.
pub(crate) fn named_if_long(p: &Poly, bits: u64) -> Poly {
    match p.as_rational() {
        Some(r) if r.numer().abs().bits().max(r.denom().bits()) > bits => {
            let value = planar_arm_core::ring::to_f64(&r).unwrap_or(f64::NAN);
            Poly::param(planar_arm_core::Param::constant(&format!("{value}"), value))
        }
        _ => p.clone(),
    }
}

/// Derives and emits `spec`. An arm whose values are all literals is derived over the
/// rationals: the same result as over polynomials, with less work.
fn derive_spec(
    arm: &Arm<'_>,
    spec: &ArmSpec<Poly>,
    header: &Header,
) -> Result<TokenStream, TokenStream> {
    match spec.as_rational() {
        Some(spec) => emit(arm, &spec, header),
        None => emit(arm, spec, header),
    }
}

fn emit<C: Emit>(
    arm: &Arm<'_>,
    spec: &ArmSpec<C>,
    header: &Header,
) -> Result<TokenStream, TokenStream> {
    let derived = Derived::new(spec);
    let mut tokens =
        generate(&derived, header).map_err(|e| emit_error(arm, &derived, &e).to_compile_error())?;
    tokens.extend(planar_arm_core::generate::closed_forms(&derived, header));
    tokens.extend(
        planar_arm_core::identification::identification(&derived, header)
            .map_err(|e| emit_error(arm, &derived, &e).to_compile_error())?,
    );
    tokens.extend(link_types(arm));
    tokens.extend(param_accessors(arm, header));
    Ok(tokens)
}

/// One accessor per run-time parameter field (`paths::param_accessor`), through which every
/// generated method reads it: a field whose type is not the primitive `f64` (a type of the
/// user's named `f64`) is then one error at its type, not one per read.
fn param_accessors(arm: &Arm<'_>, header: &Header) -> TokenStream {
    let names = arm
        .values()
        .iter()
        .flat_map(|(_, v)| v.params.iter().map(|p| p.name.clone()))
        .collect();
    param_accessors_of(names, &arm.others, header)
}

/// The accessors of [`param_accessors`] for the parameter fields `names` among `others`.
pub(crate) fn param_accessors_of(
    mut names: Vec<String>,
    others: &[&syn::Field],
    header: &Header,
) -> TokenStream {
    names.sort();
    names.dedup();
    if names.is_empty() {
        return TokenStream::new();
    }
    let accessors = names.iter().filter_map(|name| {
        let field = others
            .iter()
            .find(|f| f.ident.as_ref().is_some_and(|i| i == name))?;
        let ident = field.ident.as_ref()?;
        let accessor = planar_arm_core::paths::param_accessor(name);
        let read = quote::quote_spanned!(syn::spanned::Spanned::span(&field.ty)=>
            ::planar_arm::__private::param(&self.#ident)
        );
        Some(quote! {
            #[doc(hidden)]
            #[inline(always)]
            fn #accessor(&self) -> #F64 {
                #read
            }
        })
    });
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = header;
    quote! {
        #[automatically_derived]
        #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
        #[allow(non_snake_case)]
        impl #impl_generics #ty #where_clause {
            #(#accessors)*
        }
    }
}

/// The check that every link field is `planar_arm::Revolute`, each error at the field's type.
fn link_types(arm: &Arm<'_>) -> TokenStream {
    let checks = arm.links.iter().map(|l| {
        let ty = &l.field.ty;
        let check = match l.joint {
            JointKind::Revolute => quote!(link_field),
            JointKind::Prismatic => quote!(prismatic_field),
        };
        quote::quote_spanned!(syn::spanned::Spanned::span(ty)=> ::planar_arm::__private::#check::<#ty>();)
    });
    quote!(const _: () = { #(#checks)* };)
}

/// The engine could not emit the arm: some exact coefficient is too large for the generated
/// `const` data. Every parameter contributes, so the error points at the one with the most
/// digits, the likeliest culprit, and says which coefficient overflowed.
fn emit_error<C: Emit>(arm: &Arm<'_>, derived: &Derived<C>, err: &EmitError) -> syn::Error {
    let values = arm.values();
    // The first value of greatest height: the likeliest culprit.
    let mut worst: Option<&(String, &crate::attr::Value)> = None;
    for candidate in &values {
        if worst.is_none_or(|w| height(candidate.1) > height(w.1)) {
            worst = Some(candidate);
        }
    }
    let (what, tokens) = worst.map_or_else(
        || ("the arm".to_string(), quote!()),
        |(what, v)| (what.clone(), v.tokens.clone()),
    );
    let message = match overflowing_coefficient(derived) {
        Some((place, c)) => format!(
            "{what} makes the exact equations of motion too large to emit: the coefficient {} in {place} \
             has {} digits, more than the 38 of i128; use values nearer 1 with fewer digits, \
             for example between 0.001 and 1000",
            abbreviate(&c),
            digits(&c),
        ),
        None => format!("{what}: {}", abbreviate_digits(&err.message)),
    };
    syn::Error::new_spanned(tokens, message)
}

/// Bits in the larger of numerator and denominator, over both components of a pair.
fn height(v: &crate::attr::Value) -> u64 {
    std::iter::once(&v.value)
        .chain(v.y.as_ref())
        .flat_map(Poly::terms)
        .map(|(_, r)| r.numer().abs().bits().max(r.denom().bits()))
        .max()
        .unwrap_or(0)
}

/// The first coefficient of the emitted `const` data that does not fit in `i128`, in the
/// order the engine checks them.
fn overflowing_coefficient<C: Emit>(d: &Derived<C>) -> Option<(String, Rational)> {
    let dy = &d.dynamics;
    let mut entries: Vec<(String, &Expr<C>)> = vec![
        ("the kinetic energy".to_string(), &dy.kinetic_energy),
        ("the potential energy".to_string(), &dy.potential_energy),
    ];
    for (i, row) in dy.mass_matrix.iter().enumerate() {
        for (j, e) in row.iter().enumerate() {
            entries.push((format!("M{}{}", i + 1, j + 1), e));
        }
    }
    for (i, e) in dy.coriolis.iter().enumerate() {
        entries.push((format!("c{}", i + 1), e));
    }
    for (i, e) in dy.gravity.iter().enumerate() {
        entries.push((format!("g{}", i + 1), e));
    }
    entries.into_iter().find_map(|(place, e)| {
        e.terms()
            .flat_map(|(_, _, c)| c.parts())
            .find(|(_, c)| to_i128_pair(c).is_none())
            .map(|(_, c)| (place, c))
    })
}

/// A rational with its long digit strings shortened: `25000000...0000/3`.
fn abbreviate(r: &Rational) -> String {
    if r.is_integer() {
        shorten(&r.numer().to_string())
    } else {
        format!(
            "{}/{}",
            shorten(&r.numer().to_string()),
            shorten(&r.denom().to_string())
        )
    }
}

/// Decimal digits of the larger of numerator and denominator.
fn digits(r: &Rational) -> usize {
    r.numer()
        .abs()
        .to_string()
        .len()
        .max(r.denom().to_string().len())
}

fn shorten(s: &str) -> String {
    if s.len() <= 16 {
        s.to_string()
    } else {
        format!("{}...{}", &s[..8], &s[s.len() - 4..])
    }
}

/// Shortens every run of more than 16 digits in a message.
fn abbreviate_digits(message: &str) -> String {
    let mut out = String::new();
    let mut run = String::new();
    for ch in message.chars().chain(std::iter::once(' ')) {
        if ch.is_ascii_digit() {
            run.push(ch);
        } else {
            out.push_str(&shorten(&run));
            run.clear();
            out.push(ch);
        }
    }
    out.pop();
    out
}

/// After an error, a stub impl of every trait the derive would implement, so uses of the
/// traits do not add a cascade of errors.
fn fallback(input: &DeriveInput) -> TokenStream {
    let Some(n) = Arm::field_count(input) else {
        return TokenStream::new();
    };
    // The stub's methods are generic over `__T` too: with the struct's own `__T` (an error
    // already reported) it would only add a second one.
    if input.generics.type_params().any(|p| p.ident == "__T") {
        return TokenStream::new();
    }
    let header = header(input);
    let mut tokens = planar_arm_core::generate::stub(n, &header);
    let Header {
        impl_generics,
        ty,
        where_clause,
        ..
    } = &header;
    let unreachable = quote!({ ::core::unreachable!() });
    let svec = |k: usize| {
        let k = proc_macro2::Literal::usize_unsuffixed(k);
        quote!(::planar_arm::nalgebra::SVector<#F64, #k>)
    };
    let result = |t: TokenStream| quote!(::core::result::Result<#t, ::planar_arm::ArmError>);
    match n {
        2 => {
            let (v, ik) = (
                svec(2),
                result(quote!([::planar_arm::nalgebra::SVector<#F64, 2>; 2])),
            );
            let force = result(quote!(::planar_arm::nalgebra::Vector2<#F64>));
            tokens.extend(quote! {
                #[automatically_derived]
                #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
                impl #impl_generics ::planar_arm::kinematics::ClosedFormIk<2> for #ty #where_clause {
                    type Target = ::planar_arm::nalgebra::Point2<#F64>;
                    fn inverse_kinematics(&self, _: &::planar_arm::nalgebra::Point2<#F64>) -> #ik #unreachable
                }
                #[automatically_derived]
                #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
                impl #impl_generics ::planar_arm::kinematics::TipForce for #ty #where_clause {
                    fn tip_force(&self, _: &#v, _: &#v) -> #force #unreachable
                }
            });
        }
        3 => {
            let (v, ik) = (
                svec(3),
                result(quote!([::planar_arm::nalgebra::SVector<#F64, 3>; 2])),
            );
            let wrench = result(quote!(::planar_arm::kinematics::StaticWrench<3>));
            tokens.extend(quote! {
                #[automatically_derived]
                #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
                impl #impl_generics ::planar_arm::kinematics::ClosedFormIk<3> for #ty #where_clause {
                    type Target = ::planar_arm::nalgebra::Isometry2<#F64>;
                    fn inverse_kinematics(&self, _: &::planar_arm::nalgebra::Isometry2<#F64>) -> #ik #unreachable
                }
                #[automatically_derived]
                #[allow(clippy::nursery)] // straight-line arithmetic: no mul_add, whose rounding differs (suboptimal_flops)
                impl #impl_generics ::planar_arm::kinematics::TipWrench for #ty #where_clause {
                    fn tip_wrench(&self, _: &#v, _: &#v) -> #wrench #unreachable
                }
            });
        }
        _ => {}
    }
    tokens
}

fn field_names(input: &DeriveInput) -> Vec<proc_macro2::Ident> {
    match &input.data {
        syn::Data::Struct(s) => s
            .fields
            .iter()
            .filter(|f| crate::ast::is_link_field(f))
            .filter_map(|f| f.ident.clone())
            .collect(),
        _ => Vec::new(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use syn::parse_quote;

    /// The arms the unqualified output is checked on: each generated form (literal and
    /// parameterised values, payload, friction, prismatic joints, the closed forms of two and
    /// three links, the unrolled recursions of longer arms).
    fn arms() -> Vec<DeriveInput> {
        vec![
            parse_quote! {
                struct One { #[arm(length = 1, mass = 2)] a: Revolute }
            },
            parse_quote! {
                #[arm(gravity = 9.81, payload = 0.4)]
                struct Two {
                    #[arm(length = 1/2, mass = 1, com = (0.2, 0.01), damping = 0.1)] a: Revolute,
                    #[arm(length = 0.4, mass = 1.5, frictionloss = 0.2, armature = 0.1)] b: Revolute,
                }
            },
            parse_quote! {
                #[arm(payload = self.load, payload_inertia = self.pi, payload_com = (self.px, 0))]
                struct TwoParams {
                    #[arm(length = self.l1, mass = self.m1, inertia = self.i1, com = self.c1)] a: Revolute,
                    #[arm(length = 0.4, mass = 1, com = (self.c2, 0.01), frictionloss = 0.2)] b: Revolute,
                    l1: f64, m1: f64, i1: f64, c1: f64, c2: f64, load: f64, pi: f64, px: f64,
                }
            },
            parse_quote! {
                struct Three {
                    #[arm(length = 1, mass = 1)] a: Revolute,
                    #[arm(length = 1, mass = 1, range = (-1.5, 1.5))] b: Revolute,
                    #[arm(length = 1, mass = self.m)] c: Revolute,
                    m: f64,
                }
            },
            parse_quote! {
                #[arm(payload = 0.2)]
                struct Gantry {
                    #[arm(length = 0.1, mass = self.carriage, inertia = 0, com = 0, range = (-1, 1), damping = 2)]
                    rail: Prismatic,
                    #[arm(length = 0.4, mass = 1)] upper: Revolute,
                    #[arm(length = 0.3, mass = 1)] fore: Revolute,
                    carriage: f64,
                }
            },
            parse_quote! {
                struct Six {
                    #[arm(length = 1, mass = 1)] a: Revolute,
                    #[arm(length = 1, mass = self.m)] b: Revolute,
                    #[arm(length = 1, mass = 1)] c: Revolute,
                    #[arm(length = 1/2, mass = 1)] d: Prismatic,
                    #[arm(length = 1, mass = 1)] e: Revolute,
                    #[arm(length = 1, mass = 1, inertia = self.i)] f: Revolute,
                    m: f64, i: f64,
                }
            },
        ]
    }

    /// Without `#[arm(crate = ...)]` the output is not rewritten, so the engine must already
    /// write every primitive by its `::core` path: rewriting must change nothing.
    #[test]
    fn output_needs_no_rewriting() {
        for input in arms() {
            let out = derive(&input);
            let text = out.to_string();
            assert!(
                !text.contains("compile_error"),
                "{}: {text:.300}",
                input.ident
            );
            let rewritten = planar_arm_core::paths::qualify(out, None).to_string();
            if rewritten != text {
                let at = text
                    .bytes()
                    .zip(rewritten.bytes())
                    .take_while(|(a, b)| a == b)
                    .count();
                panic!(
                    "{}: a bare primitive at ...{}",
                    input.ident,
                    &text[at.saturating_sub(200)..(at + 60).min(text.len())]
                );
            }
        }
    }

    /// With a crate path the rewrite runs: `::planar_arm` goes, primitives stay qualified.
    #[test]
    fn a_crate_path_replaces_planar_arm() {
        let input: DeriveInput = parse_quote! {
            #[arm(crate = "arm")]
            struct One { #[arm(length = 1, mass = 2)] a: Revolute }
        };
        let text = derive(&input).to_string();
        assert!(!text.contains("planar_arm ::"), "{text:.300}");
        assert!(text.contains("impl arm :: PlanarArm < 1 >"), "{text:.300}");
        assert!(text.contains(":: core :: primitive :: f64"), "{text:.300}");
    }
}
