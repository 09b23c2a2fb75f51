#!/usr/bin/env python3
"""Writes the table of src/trig.rs: sin(k pi/128) for k = 0..255, correctly rounded.

The angles are exact multiples of pi (60 significant digits, Decimal arithmetic), not
multiples of the double nearest pi: `math.sin(k * math.pi / 128)` is off by up to 1e-16 for
150 of the 256 entries, which is 100 ulp on the results near the zeros of sin.

Run by hand: python3 scripts/sin_table.py > /tmp/table.rs, then paste it over SIN_TABLE.
"""
from decimal import Decimal, getcontext

getcontext().prec = 60
PI = Decimal("3.14159265358979323846264338327950288419716939937510582097494459230781640628620899862803482534211706798214808651")


def sin(x):
    term, total, n = x, x, 1
    while abs(term) > Decimal(10) ** -58:
        term = -term * x * x / ((2 * n) * (2 * n + 1))
        total += term
        n += 1
    return total


values = []
for k in range(256):
    angle = PI * k / 128
    if angle > PI:
        angle -= 2 * PI
    values.append(float(sin(angle)))  # float(Decimal) rounds correctly
for k in range(0, 256, 64):
    values[k] = [0.0, 1.0, 0.0, -1.0][k // 64]  # exact, and +0.0 rather than a tiny residue

print("static SIN_TABLE: [f64; 256] = [")
for v in values:
    print(f"    {v!r},")
print("];")
