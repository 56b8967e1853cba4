#pragma once
// Numbers as the bench's files write them.

#include <string>

namespace rmfx::accuracy {

// %.{significant}g; non-finite values as "inf", "-inf", "nan".
std::string numberText(double value, int significant = 6);
// Fixed decimals (times in ms); non-finite as numberText.
std::string fixedText(double value, int decimals);

}  // namespace rmfx::accuracy
