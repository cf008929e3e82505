// PythonStreamBuf: characters gathered into lines, each line written by sys.<name>.write.
#include "python/python_stream.h"

#include <pybind11/pybind11.h>

namespace py = pybind11;

namespace geomesh::python {

std::string PythonStreamBuf::append(const char* text, std::size_t count) {
  std::lock_guard lock(mutex_);
  pending_.append(text, count);
  const std::size_t end = pending_.rfind('\n');
  if (end == std::string::npos) return {};
  std::string lines = pending_.substr(0, end + 1);
  pending_.erase(0, end + 1);
  return lines;
}

PythonStreamBuf::int_type PythonStreamBuf::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const char ch = traits_type::to_char_type(c);
  write(append(&ch, 1));
  return c;
}

std::streamsize PythonStreamBuf::xsputn(const char* text, std::streamsize count) {
  write(append(text, static_cast<std::size_t>(count)));
  return count;
}

int PythonStreamBuf::sync() {
  std::string rest;
  {
    std::lock_guard lock(mutex_);
    rest.swap(pending_);
  }
  write(rest);
  return 0;
}

// Written outside the lock: a thread that holds the GIL may be waiting to append.
void PythonStreamBuf::write(const std::string& text) const {
  if (text.empty() || !Py_IsInitialized()) return;
  py::gil_scoped_acquire gil;
  try {
    // Bytes that are not UTF-8 are replaced rather than lost with the whole line.
    auto line = py::reinterpret_steal<py::object>(
        PyUnicode_DecodeUTF8(text.data(), static_cast<Py_ssize_t>(text.size()), "replace"));
    if (!line) throw py::error_already_set();
    py::module_::import("sys").attr(name_).attr("write")(line);
  } catch (const py::error_already_set&) {
    // No sys.stdout (pythonw), or one that fails: the text is dropped, the session goes on.
  }
}

}  // namespace geomesh::python
