// SPDX-License-Identifier: Apache-2.0
// The ADC transfer and the storage of counts in the output data type (adc.h).
#include "glint/detect/adc.h"

namespace glint::detect {

double adc_count(double electrons, double min_electrons, double max_electrons, int bit_depth) {
    return Adc(min_electrons, max_electrons, bit_depth).count(electrons);
}

int lossless_count_bits(io::EnviDataType type) {
    switch (type) {
        case io::EnviDataType::uint8:
            return 8;
        case io::EnviDataType::int16:
            return 15;
        case io::EnviDataType::uint16:
            return 16;
        case io::EnviDataType::int32:
            return 31;
        case io::EnviDataType::uint32:
            return 32;
        case io::EnviDataType::float32:
            return 24;
        case io::EnviDataType::int64:
            return 63;
        case io::EnviDataType::uint64:
            return 64;
        default:
            return 53;
    }
}

}  // namespace glint::detect
