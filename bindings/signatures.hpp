// chasles._core: signatures that help() and inspect.signature can read, for
// every function pybind11 made, in one place.
//
// pybind11 3.1 writes a function's signature, with types, as the first line
// of its docstring ("exp(w: numpy.typing.ArrayLike) -> chasles._core.SO3"),
// but gives it no __text_signature__ (CPython reads one only from a
// docstring that begins "exp(w)\n--\n\n"), so inspect.signature raises
// ValueError; and it makes the function's __self__ pybind11's internal
// function record, so help() titles it "exp(...) method of
// pybind11_builtins.pybind11_detail_function_record_v1_... instance".
//
// `finish_functions(m)`, called once at the end of the module's
// initialization (module.cpp), visits every function pybind11 made: the
// module's functions and the methods, static methods and property getters
// of the module's classes. For each it
// - prepends "name(params)\n--\n\n" to the docstring. CPython then serves
//   __text_signature__ "(params)" (names, kinds and defaults, no
//   annotations: inspect refuses them) and strips it from __doc__, which
//   stays pybind11's typed text, read by pybind11-stubgen for the stub;
// - makes __self__ the module, as for any function written in C, so that
//   help() shows "exp(w)". pybind11's dispatcher takes the function record
//   as its self, so each function gets a trampoline of its own (a template
//   instance with an index into a table) that hands the record over: one
//   direct call more per call, no lookup.
//
// The trampoline of a class's __init__ and __setstate__ also refuses a call
// on an object that holds a value already (TypeError): the classes are
// values, and pybind11 would otherwise ignore the call (an object its
// __init__ made) or replace the value in place (one a call made).
//
// The parameters come from pybind11's record: positional-only where
// pybind11 matches by position alone (pybind11's self of a method without
// py::arg, py::pos_only, unnamed arguments), keyword-only after py::kw_only,
// defaults written as Python literals ("1e-09", "(0.0, 0.0, 0.0)", "None")
// and as "..." (Ellipsis) where the default is an object no literal
// spells, such as SE3's SO3() (the stub writes "..." there too). The
// overloads of one function with the same parameter kinds merge position by
// position: equal names stay, different names join with "_or_" and become
// positional-only (act(self, twist_or_wrench_or_points, /)); overloads of
// different shapes give (*args, **kwargs).
//
// `def_refusal(cls, explain)` adds an overload of __init__ that takes any
// arguments the real ones refuse and raises the TypeError `explain` writes
// (what to call instead); it is left out of __doc__, of the signature and so
// of the stub: it is not an API.
#pragma once

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include <pybind11/pybind11.h>

#include "convert.hpp"

namespace chasles_py {

namespace signatures {

namespace detail = py::detail;

/// A function pybind11 made: its record chain, or nullptr for anything else
/// (a function already finished, a Python function, a numpy ufunc, ...).
inline detail::function_record* record_of(PyObject* func) {
  if (func == nullptr || !PyCFunction_Check(func)) return nullptr;
  PyObject* self = PyCFunction_GET_SELF(func);
  return self == nullptr ? nullptr : detail::function_record_ptr_from_PyObject(self);
}

/// The overloads of __init__ added by def_refusal, left out of the
/// docstrings and signatures.
inline std::vector<const detail::function_record*>& refusals() {
  static std::vector<const detail::function_record*> records;
  return records;
}

inline bool is_refusal(const detail::function_record* rec) {
  for (const auto* r : refusals())
    if (r == rec) return true;
  return false;
}

struct Param {
  enum Kind { positional_only, positional_or_keyword, var_positional, keyword_only, var_keyword };
  std::string name;
  Kind kind;
  std::string default_text;  ///< empty: no default
};

/// `value` as a Python literal that inspect's parser reads back to an equal
/// value of the same type, or "..." when there is none (an object, NaN, inf).
inline std::string literal(py::handle value) {
  // kept for the process (a static py::object would be released after the interpreter)
  static PyObject* const literal_eval =
      py::module_::import("ast").attr("literal_eval").cast<py::object>().release().ptr();
  try {
    const std::string text = py::repr(value);
    const py::object back = py::reinterpret_borrow<py::object>(literal_eval)(text);
    if (py::type::handle_of(back).is(py::type::handle_of(value)) && back.equal(value)) return text;
  } catch (py::error_already_set&) {  // no literal (literal_eval refused it), or a repr that raised
  }
  return "...";
}

/// The parameters of one overload, from pybind11's record.
inline std::vector<Param> params_of(const detail::function_record& rec) {
  std::vector<Param> out;
  const std::size_t n = rec.nargs;
  for (std::size_t i = 0; i < n; ++i) {
    const detail::argument_record* a = i < rec.args.size() ? &rec.args[i] : nullptr;
    const bool named = a != nullptr && a->name != nullptr && a->name[0] != '\0';
    Param p;
    if (named) {
      p.name = a->name;
    } else if (i == 0 && rec.is_method) {
      p.name = "self";
    } else {
      p.name = "arg" + std::to_string(i - (rec.is_method ? 1 : 0));
    }
    if (rec.has_args && i == rec.nargs_pos) {
      p.kind = Param::var_positional;
    } else if (rec.has_kwargs && i + 1 == n) {
      p.kind = Param::var_keyword;
    } else if (i < rec.nargs_pos) {
      // pybind11 matches a keyword only to a named argument record
      p.kind = (i < rec.nargs_pos_only || !named) ? Param::positional_only : Param::positional_or_keyword;
    } else {
      p.kind = Param::keyword_only;
    }
    if (a != nullptr && a->value && p.kind != Param::var_positional && p.kind != Param::var_keyword)
      p.default_text = literal(a->value);
    out.push_back(std::move(p));
  }
  return out;
}

inline bool is_positional(Param::Kind kind) {
  return kind == Param::positional_only || kind == Param::positional_or_keyword;
}

/// Whether `name` is one of the names of "a_or_b_or_c".
inline bool has_name(const std::string& joined, const std::string& name) {
  return ("_or_" + joined + "_or_").find("_or_" + name + "_or_") != std::string::npos;
}

/// The signature of the visible overloads, merged (see the file comment).
inline std::vector<Param> merged_params(const std::vector<const detail::function_record*>& overloads) {
  std::vector<Param> merged = params_of(*overloads.front());
  bool same_shape = true;
  std::size_t renamed = 0;  // parameters [0, renamed) have names that differ between overloads
  for (std::size_t k = 1; k < overloads.size() && same_shape; ++k) {
    const std::vector<Param> other = params_of(*overloads[k]);
    same_shape = other.size() == merged.size();
    for (std::size_t i = 0; i < other.size() && same_shape; ++i) {
      Param& p = merged[i];
      const Param& q = other[i];
      const bool both_positional = is_positional(p.kind) && is_positional(q.kind);
      if ((p.kind != q.kind && !both_positional) || p.default_text != q.default_text) {
        same_shape = false;
      } else if (!has_name(p.name, q.name)) {
        if (both_positional) {
          p.name += "_or_" + q.name;
          renamed = std::max(renamed, i + 1);
        } else {
          same_shape = false;
        }
      }
      if (q.kind == Param::positional_only) p.kind = Param::positional_only;
    }
  }
  if (same_shape) {
    // No one keyword reaches a renamed parameter in every overload: it is
    // positional-only, and so is every parameter before it.
    for (std::size_t i = 0; i < renamed; ++i) merged[i].kind = Param::positional_only;
    return merged;
  }
  std::vector<Param> generic;
  if (overloads.front()->is_method) generic.push_back({"self", Param::positional_only, ""});
  generic.push_back({"args", Param::var_positional, ""});
  generic.push_back({"kwargs", Param::var_keyword, ""});
  return generic;
}

/// "(a, b=1.0, /, c, *, d=None)" as inspect writes it.
inline std::string text_signature(const std::vector<Param>& params) {
  std::string s = "(";
  bool first = true, star_written = false;
  const auto sep = [&]() {
    if (!first) s += ", ";
    first = false;
  };
  for (std::size_t i = 0; i < params.size(); ++i) {
    const Param& p = params[i];
    if (p.kind == Param::keyword_only && !star_written) {
      sep();
      s += "*";
      star_written = true;
    }
    sep();
    if (p.kind == Param::var_positional) {
      s += "*";
      star_written = true;
    }
    if (p.kind == Param::var_keyword) s += "**";
    s += p.name;
    if (!p.default_text.empty()) s += "=" + p.default_text;
    if (p.kind == Param::positional_only && (i + 1 == params.size() || params[i + 1].kind != Param::positional_only)) {
      s += ", /";
    }
  }
  return s + ")";
}

/// pybind11's docstring of the visible overloads, written as pybind11 writes
/// it (initialize_generic): the typed signature line(s), then the docs.
inline std::string visible_doc(const char* name, const std::vector<const detail::function_record*>& overloads) {
  std::string doc;
  const bool chain = overloads.size() > 1;
  if (chain) doc += std::string(name) + "(*args, **kwargs)\nOverloaded function.\n\n";
  int index = 0;
  for (const auto* rec : overloads) {
    if (index > 0) doc += '\n';
    if (chain)
      doc += std::to_string(++index) + ". ";
    else
      ++index;
    doc += std::string(name) + rec->signature + "\n";
    if (rec->doc != nullptr && rec->doc[0] != '\0') doc += "\n" + std::string(rec->doc) + "\n";
  }
  return doc;
}

/// CPython's METH_FASTCALL | METH_KEYWORDS function, as it calls ml_meth.
using FastCall = PyObject* (*)(PyObject*, PyObject* const*, Py_ssize_t, PyObject*);
/// pybind11's dispatcher (cpp_function::dispatcher), as pybind11 3.1 declares it.
using Dispatcher = PyObject* (*)(PyObject*, PyObject* const*, size_t, PyObject*);

/// What a finished function's PyMethodDef and trampoline read. Kept for the
/// life of the process, as the functions themselves are.
struct Finished {
  PyMethodDef def{};
  PyObject* record = nullptr;   ///< pybind11's function record (a strong reference)
  Dispatcher dispatch = nullptr;  ///< pybind11's dispatcher
  PyTypeObject* constructs = nullptr;  ///< for __init__ and __setstate__: their class (else null)
};

inline constexpr std::size_t kMaxFunctions = 1024;

/// One entry per finished function (constant-initialized: no guard on the
/// trampolines' path).
inline std::array<Finished, kMaxFunctions> finished_table{};
inline std::size_t finished_count = 0;

/// Whether self, an instance of the bound class `type`, holds a value
/// already (its __init__ or __setstate__ ran, or a call made it).
inline bool holds_value(PyObject* self, PyTypeObject* type) {
  if (!PyObject_TypeCheck(self, type)) return false;  // pybind11's dispatcher refuses it
  auto* inst = reinterpret_cast<detail::instance*>(self);
  for (const auto& vh : detail::values_and_holders(inst))
    if (vh.holder_constructed()) return true;
  return false;
}

/// The TypeError of __init__ or __setstate__ called again on a live object
/// (nullptr, the error set).
/// pybind11 ignores such a call for an object its own __init__ made (and
/// returns None), and runs it for one a call made (bindings/instance.hpp),
/// replacing the value of an object that may be shared: the classes are
/// values, a new one is made instead.
inline PyObject* refuse_initialized(PyObject* self, const char* method) {
  const char* full = Py_TYPE(self)->tp_name;  // "chasles._core.SE3"
  const char* dot = std::strrchr(full, '.');
  const std::string name = dot ? dot + 1 : full;
  const std::string msg = name + "." + method + ": the " + name +
                          " is already initialized; its value does not change (make a new " + name + " instead)";
  PyErr_SetString(PyExc_TypeError, msg.c_str());
  return nullptr;
}

template <std::size_t I>
PyObject* trampoline(PyObject* /*module*/, PyObject* const* args, Py_ssize_t nargs, PyObject* kwnames) {
  const Finished& f = finished_table[I];
  if (f.constructs != nullptr && nargs > 0 && holds_value(args[0], f.constructs))
    return refuse_initialized(args[0], f.def.ml_name);
  return f.dispatch(f.record, args, static_cast<size_t>(nargs), kwnames);
}

template <std::size_t... I>
constexpr std::array<FastCall, sizeof...(I)> make_trampolines(std::index_sequence<I...>) {
  return {{&trampoline<I>...}};
}

inline constexpr std::array<FastCall, kMaxFunctions> kTrampolines =
    make_trampolines(std::make_index_sequence<kMaxFunctions>{});

/// Finishes one function (see the file comment); `name` is what help() calls
/// it (pybind11 leaves property getters unnamed).
inline void finish(py::handle func, const std::string& name, py::handle module) {
  std::size_t& count = finished_count;
  detail::function_record* head = record_of(func.ptr());
  if (head == nullptr || std::strncmp(head->name, "_pybind11", 9) == 0) return;
  auto* f = reinterpret_cast<PyCFunctionObject*>(func.ptr());
  if (f->m_ml->ml_flags != (METH_FASTCALL | METH_KEYWORDS))
    py::pybind11_fail("chasles: unexpected calling convention of the pybind11 function " + name);
  if (count == kMaxFunctions)
    py::pybind11_fail("chasles: more functions than kMaxFunctions; raise it in signatures.hpp");

  std::vector<const detail::function_record*> visible;
  bool hidden = false;
  for (const detail::function_record* rec = head; rec != nullptr; rec = rec->next) {
    if (is_refusal(rec)) {
      hidden = true;
    } else {
      visible.push_back(rec);
    }
  }
  if (visible.empty()) return;
  const char* old_doc = f->m_ml->ml_doc;
  const std::string doc = hidden || old_doc == nullptr ? visible_doc(head->name, visible) : std::string(old_doc);
  const std::string text = name + text_signature(merged_params(visible)) + "\n--\n\n" + doc;

  Finished& entry = finished_table[count];
  entry.dispatch = reinterpret_cast<Dispatcher>(reinterpret_cast<void (*)()>(f->m_ml->ml_meth));
  entry.record = f->m_self;  // the function's reference, now the table's
  entry.def.ml_name = strdup(name.c_str());
  entry.def.ml_meth = reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(kTrampolines[count]));
  entry.def.ml_flags = f->m_ml->ml_flags;
  entry.def.ml_doc = strdup(text.c_str());
  if (head->is_constructor && head->scope && PyType_Check(head->scope.ptr()))
    entry.constructs = reinterpret_cast<PyTypeObject*>(head->scope.ptr());
  Py_INCREF(module.ptr());
  f->m_self = module.ptr();
  f->m_ml = &entry.def;
  if (f->m_module == nullptr) {  // pybind11 leaves property accessors without a __module__
    f->m_module = py::str(module.attr("__name__")).release().ptr();
  }
  ++count;
}

/// Finishes the function(s) inside a class attribute: an instance method, a
/// static method, a property's accessors, or a function.
inline void finish_member(py::handle value, const std::string& name, py::handle module) {
  PyObject* v = value.ptr();
  if (PyCFunction_Check(v)) {
    finish(value, name, module);
  } else if (PyInstanceMethod_Check(v)) {
    finish(PyInstanceMethod_GET_FUNCTION(v), name, module);
  } else if (PyObject_TypeCheck(v, &PyStaticMethod_Type)) {
    finish(value.attr("__func__"), name, module);
  } else if (PyObject_TypeCheck(v, &PyProperty_Type)) {
    for (const char* accessor : {"fget", "fset", "fdel"}) {
      const py::object fn = value.attr(accessor);
      if (!fn.is_none()) finish(fn, name, module);
    }
  }
}

}  // namespace signatures

/// See the file comment: signatures for every function of the module `m`
/// and of its classes. Call once, after every bind_*.
inline void finish_functions(py::module_& m) {
  const std::string module_name = py::str(m.attr("__name__"));
  const py::dict items = m.attr("__dict__");
  for (const auto& item : items) {
    const py::handle value = item.second;
    const std::string name = py::str(item.first);
    if (PyType_Check(value.ptr())) {
      if (!py::hasattr(value, "__module__") || py::str(value.attr("__module__")).cast<std::string>() != module_name)
        continue;
      const py::dict members = value.attr("__dict__");
      for (const auto& member : members) signatures::finish_member(member.second, py::str(member.first), m);
    } else {
      signatures::finish(value, name, m);
    }
  }
}

/// Hides the last overload of the pybind11 function `fn` (see def_refusal).
inline void hide_last_overload(PyObject* fn, const char* what) {
  py::detail::function_record* rec = signatures::record_of(fn);
  if (rec == nullptr) py::pybind11_fail(std::string("chasles: def_refusal: ") + what + " is not a pybind11 function");
  while (rec->next != nullptr) rec = rec->next;
  signatures::refusals().push_back(rec);
}

/// An overload of __init__ for every call the real ones refuse: it raises
/// the TypeError whose text `explain(args, kwargs)` returns, and is hidden
/// from the docstring, the signature and the stub (see the file comment).
template <typename Class, typename Explain>
void def_refusal(Class& cls, Explain explain) {
  using T = typename Class::type;
  cls.def(py::init(
      [explain](const py::args& args, const py::kwargs& kwargs) -> T { raise_type_error(explain(args, kwargs)); }));
  // The overload just added is the last of __init__'s chain.
  const py::object init = cls.attr("__init__");
  hide_last_overload(PyInstanceMethod_Check(init.ptr()) ? PyInstanceMethod_GET_FUNCTION(init.ptr()) : init.ptr(),
                     "__init__");
}

/// The same for the static method `name` (defined before).
template <typename Class, typename Explain>
void def_static_refusal(Class& cls, const char* name, Explain explain) {
  cls.def_static(name, [explain](const py::args& args, const py::kwargs& kwargs) -> py::object {
    raise_type_error(explain(args, kwargs));
  });
  hide_last_overload(py::getattr(cls, name).ptr(), name);
}

}  // namespace chasles_py
