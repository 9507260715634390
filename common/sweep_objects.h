#pragma once
// Objects through run_sweep (common/sweep.h): a case returns its result object as one row that holds
// the object's binary archive (Boost.Serialization: the object's own member list, one place), 8
// bytes per double; every rank unpacks the rows into the same objects, bit for bit. For results
// richer than a row of numbers (the dynamics: modes, responses, time series).
#include "common/sweep.h"

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>

#include <cstring>
#include <sstream>
#include <string>

namespace servodrift
{
  namespace detail
  {
    std::vector<double> pack_bytes(const std::string &bytes);
    std::string unpack_bytes(const std::vector<double> &row);
  } // namespace detail

  /// The row that carries `object' through run_sweep.
  template <class T>
  std::vector<double> row_of(const T &object)
  {
    std::ostringstream out;
    {
      boost::archive::binary_oarchive archive(out);
      archive << object;
    }
    return detail::pack_bytes(out.str());
  }

  /// The object a row of row_of() carries.
  template <class T>
  T object_of(const std::vector<double> &row)
  {
    std::istringstream in(detail::unpack_bytes(row));
    boost::archive::binary_iarchive archive(in);
    T object;
    archive >> object;
    return object;
  }
} // namespace servodrift
