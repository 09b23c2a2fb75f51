//! The derivation as text: plain formulas (`Display`) and LaTeX ([`Latex`]).

use core::fmt::{self, Display, Formatter, Write as _};

use super::{Angle, Derivation, Rational, SpatialDerivation, Term, Terms, Trig, Var};

/// How a formula is written.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Style {
    /// `5/3 + cos(q2) - 1/2 m2 sin(q2 + q3) qd1 qd2`.
    Plain,
    /// `\frac{5}{3} + \cos q_{2} - \frac{1}{2} m_{2} \sin(q_{2} + q_{3}) \dot{q}_{1} \dot{q}_{2}`.
    Latex,
}

/// A LaTeX rendering of a sum ([`Terms::latex`]) or of a whole derivation
/// ([`Derivation::latex`], an `aligned` block), for a paper or a notebook.
///
/// Run-time parameters named like `m2` are written `m_{2}`, longer names upright
/// (`\mathrm{load}`); rates are `\dot{q}_{j}`, accelerations `\ddot{q}_{j}`.
///
/// # Example
///
/// ```
/// use planar_arm::prelude::*;
///
/// #[derive(PlanarArm)]
/// #[arm(gravity = 0)]
/// struct Paper2 {
///     #[arm(length = 1, mass = 1)]
///     upper: Revolute,
///     #[arm(length = 1, mass = 1)]
///     fore: Revolute,
/// }
///
/// let m11 = <Paper2 as PlanarArm<2>>::EXACT.mass_matrix[0][0];
/// assert_eq!(m11.to_string(), "5/3 + cos(q2)");
/// assert_eq!(m11.latex().to_string(), r"\frac{5}{3} + \cos q_{2}");
/// ```
#[derive(Clone, Copy)]
pub struct Latex<'a, T: ?Sized>(pub &'a T);

impl Terms {
    /// This sum in LaTeX (see [`Latex`]).
    #[must_use]
    pub const fn latex(&self) -> Latex<'_, Self> {
        Latex(self)
    }
}

impl<const N: usize> SpatialDerivation<N> {
    /// Every formula in LaTeX, one `aligned` line each (see [`Latex`]).
    #[must_use]
    pub const fn latex(&self) -> Latex<'_, Self> {
        Latex(self)
    }
}

impl<const N: usize> Derivation<N> {
    /// Every formula of the derivation in LaTeX, one `aligned` line each (see [`Latex`]).
    #[must_use]
    pub const fn latex(&self) -> Latex<'_, Self> {
        Latex(self)
    }
}

fn rational(f: &mut Formatter<'_>, r: Rational, style: Style) -> fmt::Result {
    match (r.denom == 1, style) {
        (true, _) => write!(f, "{}", r.numer),
        (false, Style::Plain) => write!(f, "{}/{}", r.numer, r.denom),
        (false, Style::Latex) => {
            let sign = if r.numer < 0 { "-" } else { "" };
            write!(f, "{sign}\\frac{{{}}}{{{}}}", r.numer.abs(), r.denom)
        }
    }
}

/// `q2` or `q_{2}`.
fn joint(f: &mut Formatter<'_>, symbol: &str, j: usize, style: Style) -> fmt::Result {
    match style {
        Style::Plain => write!(f, "{symbol}{}", j + 1),
        Style::Latex => write!(f, "{symbol}_{{{}}}", j + 1),
    }
}

fn angle(f: &mut Formatter<'_>, a: Angle, style: Style) -> fmt::Result {
    let mut first = true;
    for (j, k) in a.coefficients().enumerate().filter(|&(_, k)| k != 0) {
        match (first, k < 0) {
            (true, true) => f.write_char('-')?,
            (true, false) => {}
            (false, true) => f.write_str(" - ")?,
            (false, false) => f.write_str(" + ")?,
        }
        first = false;
        if k.abs() != 1 {
            write!(f, "{} ", k.abs())?;
        }
        joint(f, "q", j, style)?;
    }
    Ok(())
}

/// A run-time parameter's name: `m2` as `m_{2}`, `load` as `\mathrm{load}`.
fn parameter(f: &mut Formatter<'_>, name: &str, style: Style) -> fmt::Result {
    if style == Style::Plain {
        return f.write_str(name);
    }
    let stem = name.trim_end_matches(|c: char| c.is_ascii_digit());
    let index = &name[stem.len()..];
    if stem.chars().count() == 1 {
        f.write_str(stem)?;
    } else {
        f.write_str("\\mathrm{")?;
        for c in stem.chars() {
            if c == '_' {
                f.write_str("\\_")?;
            } else {
                f.write_char(c)?;
            }
        }
        f.write_char('}')?;
    }
    if !index.is_empty() {
        write!(f, "_{{{index}}}")?;
    }
    Ok(())
}

fn exponent(f: &mut Formatter<'_>, e: u32, style: Style) -> fmt::Result {
    match (e > 1, style) {
        (false, _) => Ok(()),
        (true, Style::Plain) => write!(f, "^{e}"),
        (true, Style::Latex) => write!(f, "^{{{e}}}"),
    }
}

/// One term after its sign: `|coeff| params trig rates`.
fn term_magnitude(f: &mut Formatter<'_>, t: &Term, style: Style) -> fmt::Result {
    let magnitude = Rational {
        numer: t.coeff.numer.abs(),
        denom: t.coeff.denom,
    };
    let mut factors = 0;
    if magnitude.numer != magnitude.denom {
        rational(f, magnitude, style)?;
        factors += 1;
    }
    let mut sep = |f: &mut Formatter<'_>| {
        factors += 1;
        if factors > 1 {
            f.write_char(' ')
        } else {
            Ok(())
        }
    };
    for (name, e) in t.params {
        sep(f)?;
        parameter(f, name, style)?;
        exponent(f, e, style)?;
    }
    if let Trig::Cos(a) | Trig::Sin(a) = t.trig {
        sep(f)?;
        let fun = match (t.trig, style) {
            (Trig::Cos(_), Style::Plain) => "cos",
            (_, Style::Plain) => "sin",
            (Trig::Cos(_), Style::Latex) => "\\cos",
            (_, Style::Latex) => "\\sin",
        };
        let single = a.coefficients().filter(|&k| k != 0).count() == 1
            && a.coefficients().all(|k| k == 0 || k == 1);
        if style == Style::Latex && single {
            write!(f, "{fun} ")?;
            angle(f, a, style)?;
        } else {
            write!(f, "{fun}(")?;
            angle(f, a, style)?;
            f.write_char(')')?;
        }
    }
    for (v, e) in t.powers {
        sep(f)?;
        match (v, style) {
            (Var::Qd(j), Style::Plain) => joint(f, "qd", j, style)?,
            (Var::Qdd(j), Style::Plain) => joint(f, "qdd", j, style)?,
            (Var::Qd(j), Style::Latex) => joint(f, "\\dot{q}", j, style)?,
            (Var::Qdd(j), Style::Latex) => joint(f, "\\ddot{q}", j, style)?,
            (Var::Q(j), _) => joint(f, "q", j, style)?,
        }
        exponent(f, e, style)?;
    }
    if factors == 0 {
        f.write_char('1')?;
    }
    Ok(())
}

fn terms(f: &mut Formatter<'_>, sum: &Terms, style: Style) -> fmt::Result {
    let mut first = true;
    for t in sum.iter() {
        let negative = t.coeff.numer < 0;
        match (first, negative) {
            (true, true) => f.write_char('-')?,
            (true, false) => {}
            (false, true) => f.write_str(" - ")?,
            (false, false) => f.write_str(" + ")?,
        }
        first = false;
        term_magnitude(f, &t, style)?;
    }
    if first {
        f.write_char('0')?;
    }
    Ok(())
}

/// Each formula on its own line, `name = sum`; `M` by its upper triangle (it is symmetric).
fn derivation<const N: usize>(
    f: &mut Formatter<'_>,
    d: &Derivation<N>,
    style: Style,
) -> fmt::Result {
    let (open, eq, end, close) = match style {
        Style::Plain => ("", " = ", "\n", ""),
        Style::Latex => ("\\begin{aligned}\n", " &= ", " \\\\\n", "\\end{aligned}"),
    };
    f.write_str(open)?;
    let line = |f: &mut Formatter<'_>, name: &dyn Display, sum: &Terms, last: bool| {
        write!(f, "{name}{eq}")?;
        terms(f, sum, style)?;
        f.write_str(if last && style == Style::Latex {
            "\n"
        } else {
            end
        })
    };
    line(f, &"T", &d.kinetic_energy, false)?;
    line(f, &"V", &d.potential_energy, false)?;
    let sub = |i: usize, j: Option<usize>| Subscripted { style, i, j };
    for i in 0..N {
        for j in i..N {
            line(f, &Named("M", sub(i, Some(j))), &d.mass_matrix[i][j], false)?;
        }
    }
    for i in 0..N {
        line(f, &Named("c", sub(i, None)), &d.coriolis[i], false)?;
    }
    for i in 0..N {
        line(f, &Named("g", sub(i, None)), &d.gravity[i], i + 1 == N)?;
    }
    f.write_str(close)
}

/// The spatial derivation: the tool pose's rotation `R11 .. R33` and position `p1 .. p3`, V,
/// `g1 .. gN`, then where they were multiplied out `M11 .. MNN` (upper triangle) and
/// `c1 .. cN`.
fn spatial_derivation<const N: usize>(
    f: &mut Formatter<'_>,
    d: &SpatialDerivation<N>,
    style: Style,
) -> fmt::Result {
    let Some(d) = &d.expansion else {
        return f.write_str(
            "(not multiplied out: more than 4 000 terms; the generated code evaluates the \
             product of the joints' transformations)",
        );
    };
    let (open, eq, end, close) = match style {
        Style::Plain => ("", " = ", "\n", ""),
        Style::Latex => ("\\begin{aligned}\n", " &= ", " \\\\\n", "\\end{aligned}"),
    };
    f.write_str(open)?;
    let line = |f: &mut Formatter<'_>, name: &dyn Display, sum: &Terms, last: bool| {
        write!(f, "{name}{eq}")?;
        terms(f, sum, style)?;
        f.write_str(if last && style == Style::Latex {
            "\n"
        } else {
            end
        })
    };
    let sub = |i: usize, j: Option<usize>| Subscripted { style, i, j };
    for i in 0..3 {
        for j in 0..3 {
            line(f, &Named("R", sub(i, Some(j))), &d.tip[i][j], false)?;
        }
    }
    for i in 0..3 {
        line(f, &Named("p", sub(i, None)), &d.tip[i][3], false)?;
    }
    line(f, &"V", &d.potential_energy, N == 0)?;
    let dynamics = d.mass_matrix.as_ref().zip(d.coriolis.as_ref());
    for i in 0..N {
        line(
            f,
            &Named("g", sub(i, None)),
            &d.gravity[i],
            i + 1 == N && dynamics.is_none(),
        )?;
    }
    if let Some((m, c)) = dynamics {
        for (i, row) in m.iter().enumerate() {
            for (j, entry) in row.iter().enumerate().skip(i) {
                line(f, &Named("M", sub(i, Some(j))), entry, false)?;
            }
        }
        for (i, entry) in c.iter().enumerate() {
            line(f, &Named("c", sub(i, None)), entry, i + 1 == N)?;
        }
    }
    f.write_str(close)
}

impl<const N: usize> Display for SpatialDerivation<N> {
    /// `R11 = ...` to `R33`, `p1 = ...` to `p3` (the tool pose), `V = ...`, `g1 = ...`, then
    /// `M11 = ...` (upper triangle) and `c1 = ...` where they were multiplied out, a line each.
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        spatial_derivation(f, self, Style::Plain)
    }
}

impl<const N: usize> Display for Latex<'_, SpatialDerivation<N>> {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        spatial_derivation(f, self.0, Style::Latex)
    }
}

/// `M12` or `M_{12}`.
struct Named(&'static str, Subscripted);

struct Subscripted {
    style: Style,
    i: usize,
    j: Option<usize>,
}

impl Display for Named {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        let Subscripted { style, i, j } = self.1;
        let index = match j {
            // Past nine joints the indices need a separator to be read.
            Some(j) if i >= 9 || j >= 9 => Pair::Separated(i + 1, j + 1),
            Some(j) => Pair::Joined(i + 1, j + 1),
            None => Pair::One(i + 1),
        };
        match style {
            Style::Plain => write!(f, "{}{index}", self.0),
            Style::Latex => write!(f, "{}_{{{index}}}", self.0),
        }
    }
}

enum Pair {
    One(usize),
    Joined(usize, usize),
    Separated(usize, usize),
}

impl Display for Pair {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        match *self {
            Self::One(i) => write!(f, "{i}"),
            Self::Joined(i, j) => write!(f, "{i}{j}"),
            Self::Separated(i, j) => write!(f, "{i},{j}"),
        }
    }
}

impl Display for Rational {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        rational(f, *self, Style::Plain)
    }
}

impl Display for Angle {
    /// `q2 + q3`, `q1 - 2 q2`.
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        angle(f, *self, Style::Plain)
    }
}

impl Display for Term {
    /// `-1/2 m2 sin(q2 + q3) qd1 qd2`.
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        if self.coeff.numer < 0 {
            f.write_char('-')?;
        }
        term_magnitude(f, self, Style::Plain)
    }
}

impl Display for Terms {
    /// `5/3 + cos(q2) - 1/2 m2 sin(q2 + q3) qd1 qd2`.
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        terms(f, self, Style::Plain)
    }
}

impl<const N: usize> Display for Derivation<N> {
    /// `T = ...`, `V = ...`, `M11 = ...` (the upper triangle), `c1 = ...`, `g1 = ...`, a line
    /// each.
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        derivation(f, self, Style::Plain)
    }
}

impl Display for Latex<'_, Terms> {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        terms(f, self.0, Style::Latex)
    }
}

impl<const N: usize> Display for Latex<'_, Derivation<N>> {
    fn fmt(&self, f: &mut Formatter<'_>) -> fmt::Result {
        derivation(f, self.0, Style::Latex)
    }
}
