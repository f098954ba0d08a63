#pragma once
// Port values between Python and Darkroom: numbers, text, colours and
// vectors as sequences, rows as dicts (or their text), images as Image.
#include <darkroom/port.h>
#include <darkroom/value.h>

#include <pybind11/pybind11.h>

#include <string>

namespace darkroom::python {

// The value for `port`; a wrong Python type is a TypeError naming `what`
// (e.g. "node 'colour' input 'colormap'") and what the port takes.
Value toValue(const PortSpec& port, const pybind11::handle& object, const std::string& what);
pybind11::object fromValue(PortType type, const Value& value);

}  // namespace darkroom::python
