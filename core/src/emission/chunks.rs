//! Long method bodies in blocks, which rustc's debug information can nest.

use std::collections::BTreeMap;

use proc_macro2::{Ident, TokenStream, TokenTree};
use quote::quote;

/// The most `let`s in one block of a generated method.
///
/// Each `let` opens a scope that nests until the end of its block, and LLVM builds the debug
/// information of nested scopes recursively: a method of several thousand `let`s (the
/// regressor of a 30-link arm has 4,000) overflowed rustc's stack in a `dev` build
/// (`debuginfo = 2`), where 2,700 still compiled.
const CHUNK: usize = 1000;

/// `statements[prefix..]` in blocks of at most [`CHUNK`] `let`s, each block handing on what
/// later statements read: `let (a, b, ...) = { ...; (a, b, ...) };`. A method of fewer
/// statements comes back as one token stream.
pub(super) fn chunked(
    statements: Vec<Vec<TokenTree>>,
    prefix: usize,
    defined: &[(usize, Ident)],
    last_read: &[usize],
) -> Vec<TokenStream> {
    if statements.len() - prefix <= CHUNK {
        return vec![statements.into_iter().flatten().collect()];
    }
    let name_of: BTreeMap<usize, &Ident> = defined.iter().map(|(s, i)| (*s, i)).collect();
    let mut out = Vec::new();
    let mut it = statements.into_iter().enumerate().peekable();
    while let Some((_, st)) = it.next_if(|(s, _)| *s < prefix) {
        out.push(st.into_iter().collect());
    }
    let rest: Vec<(usize, Vec<TokenTree>)> = it.collect();
    for chunk in rest.chunks(CHUNK) {
        let end = chunk.last().map_or(0, |c| c.0 + 1);
        let handed: Vec<&Ident> = chunk
            .iter()
            .filter(|(s, _)| last_read[*s] >= end)
            .filter_map(|(s, _)| name_of.get(s).copied())
            .collect();
        let body: TokenStream = chunk
            .iter()
            .flat_map(|(_, st)| st.iter().cloned())
            .collect();
        out.push(quote!(let (#(#handed,)*) = { #body (#(#handed,)*) };));
    }
    out
}
