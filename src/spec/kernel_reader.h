// The reader of a [[kernel]] table (kernel_reader.cpp), for the derivation's reader
// (reader.cpp).
#pragma once

#include "spec/derivation.h"
#include "spec/table_reader.h"

namespace impact::spec::detail {

/// The kernel `in` describes; throws `impact::error` at a field of the wrong shape.
kernel read_kernel(table_reader& in);

} // namespace impact::spec::detail
