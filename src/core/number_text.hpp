// Numbers as text for CSV and the other text outputs, without ever reading past a buffer: std::to_chars into an
// array sized for the longest double (snprintf returns the length it *would* have written, which callers once
// advanced by and so copied bytes past their buffer for values of 1e43 and more).
#pragma once
#include <string>

namespace t2imu {

// `v` with at most `decimals` (0..17) digits after the point, trailing zeros dropped: "0", "0.05", "-9.8066";
// "-0" is written "0". Any double is written in full (1e300 as its 301 digits); non-finite values as "nan",
// "inf", "-inf" (writers check their values' ranges first and refuse those).
void append_fixed(std::string& out, double v, int decimals);
std::string fixed_text(double v, int decimals);

// `v` in at most `significant` (1..17) significant digits, as printf's %.*g: "0.1", "1e+20", "-2.5e-07".
std::string general_text(double v, int significant);

}  // namespace t2imu
