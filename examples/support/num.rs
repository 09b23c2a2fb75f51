//! Numbers for people to read in the examples' output and pictures: `0.27`, `7.4` and
//! `5.1e-6` rather than `2.72e-1`, `7.4e0` and `0.0000051`, and never `-0`.
//!
//! Included by the examples that print numbers (`#[path = "support/num.rs"] mod num;`); each
//! uses a part of it.
#![allow(dead_code)]

/// `x` to `digits` significant digits: fixed notation from 0.001 up to 99999 (the integer part
/// in full, even where it has more digits), `1.2e-9` beyond that; exact zero is `0`.
pub fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return format!("{x}");
    }
    if x == 0.0 {
        return "0".into();
    }
    let digits = digits.max(1);
    // The exponent of the rounded value: 9.96 to two digits is 10, not 9.9e0.
    let mantissa = format!("{:.*e}", digits - 1, x);
    let (m, e) = mantissa.split_once('e').unwrap_or((&mantissa, "0"));
    let e: i32 = e.parse().unwrap_or(0);
    if (-3..5).contains(&e) {
        let decimals = usize::try_from(i32::try_from(digits).unwrap_or(17) - 1 - e).unwrap_or(0);
        fixed(x, decimals)
    } else {
        format!("{m}e{e}")
    }
}

/// `x` with `decimals` decimals; a value that rounds to zero is `0.00`, not `-0.00`.
pub fn fixed(x: f64, decimals: usize) -> String {
    let s = format!("{x:.decimals$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.bytes().all(|b| b == b'0' || b == b'.') => rest.to_string(),
        _ => s,
    }
}

/// A tick label: the shortest decimal that names the value (`0.5`, `2`, `-1.5`), rounding
/// noise and `-0` removed.
pub fn tick(v: f64) -> String {
    // Adding 0.0 turns -0.0 into 0.0.
    format!("{}", (v * 1e6).round() / 1e6 + 0.0)
}

/// A tick label on a logarithmic axis: `1e-6`, `0.001`, `1`, `100`, `1e4`; from 1e4 up in
/// powers of ten, which `10000`, `100000` would not show at a glance.
pub fn log_tick(v: f64) -> String {
    let s = format!("{v:.0e}");
    match s.split_once('e').map(|(_, e)| e.parse::<i32>()) {
        Some(Ok(e)) if e >= 4 => s,
        _ => sig(v, 1),
    }
}

/// A complex number with `decimals` decimals, `a+bi`; a real one (its imaginary part rounds
/// to zero) as just `a`.
pub fn complex(re: f64, im: f64, decimals: usize) -> String {
    let b = fixed(im.abs(), decimals);
    if b.bytes().all(|c| c == b'0' || c == b'.') {
        fixed(re, decimals)
    } else {
        let sign = if im < 0.0 { '-' } else { '+' };
        format!("{}{sign}{b}i", fixed(re, decimals))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_like_a_person_wrote_it() {
        assert_eq!(sig(0.0, 3), "0");
        assert_eq!(sig(-0.0, 3), "0");
        assert_eq!(sig(7.37, 2), "7.4");
        assert_eq!(sig(0.272, 3), "0.272");
        assert_eq!(sig(5.09e-6, 2), "5.1e-6");
        assert_eq!(sig(9.96, 2), "10");
        assert_eq!(sig(7.007e5, 3), "7.01e5");
        assert_eq!(sig(12345.0, 2), "12345");
        assert_eq!(sig(0.001, 1), "0.001");
        assert_eq!(sig(-4.07, 3), "-4.07");
        assert_eq!(fixed(-0.0001, 3), "0.000");
        assert_eq!(fixed(-0.0, 0), "0");
        assert_eq!(fixed(-1.5, 1), "-1.5");
        assert_eq!(complex(0.97, -0.0001, 3), "0.970");
        assert_eq!(complex(-2.694, -0.106, 3), "-2.694-0.106i");
        assert_eq!(tick(-0.0), "0");
        assert_eq!(log_tick(1e-14), "1e-14");
        assert_eq!(log_tick(100.0), "100");
        assert_eq!(log_tick(1e4), "1e4");
        assert_eq!(log_tick(9_999.999_999), "1e4");
        assert_eq!(log_tick(3e5), "3e5");
    }
}
