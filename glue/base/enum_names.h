// tiershade base: the names of a small enum as one table (a row per value) and the lookups both
// ways, so that each enum's name and parse functions read the same rows instead of two switches.
#pragma once
#include <cstddef>
#include <string>

template <class E>
struct EnumName {
  E value;
  const char *name;
};

// The name of v in the table; "?" for a value without a row.
template <class E, size_t N>
const char *enum_name(const EnumName<E> (&table)[N], E v) {
  for (const EnumName<E> &row : table)
    if (row.value == v) return row.name;
  return "?";
}

// The value whose name is s; false (and *out unchanged) when no row has that name.
template <class E, size_t N>
bool enum_parse(const EnumName<E> (&table)[N], const std::string &s, E *out) {
  for (const EnumName<E> &row : table)
    if (s == row.name) {
      *out = row.value;
      return true;
    }
  return false;
}
