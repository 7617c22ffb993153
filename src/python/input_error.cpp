// frictionlab.InputError: bad input (a scene, an override, an argument, a log), a ValueError whose
// message is what the frictionlab command prints for it ("file:line:column: error: ..."), with
// its fields spelled as arguments ("spacing: error: ..."), and the location as attributes. The
// C++ errors the command reports as bad input (exit status 2) are translated to it:
// fl::InputError, fl::UnitError, fl::DomainError and fl::VideoUnavailable.
#include <Python.h>

#include <exception>
#include <string>

#include "core/analytic_model.hpp"
#include "core/units.hpp"
#include "io/input_error.hpp"
#include "lab/video/video_settings.hpp"
#include "python/bindings.hpp"
#include "python/field_spelling.hpp"

namespace fl::python {
namespace {

// The class, made once per process; kept for the life of the interpreter.
PyObject* g_input_error = nullptr;

void raise_input_error(const std::string& message, const SourceLocation& where) {
  py::object error = py::reinterpret_borrow<py::object>(g_input_error)(spelled(message));
  error.attr("file") = where.file.empty() ? py::object(py::none()) : py::cast(where.file);
  error.attr("field") = where.field.empty() ? py::object(py::none()) : py::cast(where.field);
  error.attr("line") = where.line > 0 ? py::object(py::int_(where.line)) : py::none();
  error.attr("column") = where.column > 0 ? py::object(py::int_(where.column)) : py::none();
  PyErr_SetObject(g_input_error, error.ptr());
}

}  // namespace

void bind_input_error(py::module_& m) {
  g_input_error = PyErr_NewExceptionWithDoc(
      "frictionlab.InputError",
      "Bad input: a scene, an override, an argument or a log the lab cannot use.\n\n"
      "str(error) is the message the frictionlab command prints for it, located as compilers\n"
      "locate theirs (\"scenes/x.yaml:12:5: error: ...\"); file, line and column hold the\n"
      "location (None where it is unknown, e.g. for an argument), field the argument it is\n"
      "about (None for a file).",
      PyExc_ValueError, nullptr);
  if (g_input_error == nullptr) throw py::error_already_set();
  m.add_object("InputError", py::handle(g_input_error));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      raise_input_error(e.what(), e.where());
    } catch (const UnitError& e) {
      raise_input_error(std::string("error: ") + e.what(), {});
    } catch (const DomainError& e) {
      raise_input_error(std::string("error: ") + e.what(), {});
    } catch (const VideoUnavailable& e) {
      raise_input_error(std::string("error: ") + e.what(), {});
    }
  });
}

}  // namespace fl::python
