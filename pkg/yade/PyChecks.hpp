// Python attributes whose wrong type is reported with the attribute's name. Boost.Python's own
// converters say only "Python argument types in None.None(MesoMat, str) did not match ...".
// The YADE-registered property is replaced by one that takes any object and checks it (its
// docstring is kept); constructors check their keywords the same way (checkKeywords).
#pragma once
#include <boost/python.hpp>
#include <boost/shared_ptr.hpp>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace yade {
namespace pychecks {

	enum class Kind { Number, Text, Flag, Integer };

	inline std::string digits(double v) // all digits: a rejected 1e-20 must not read "0.000000"
	{
		std::ostringstream out;
		out.precision(17);
		out << v;
		return out.str();
	}

	inline std::string describe(const boost::python::object& v)
	{
		const std::string repr = boost::python::extract<std::string>(boost::python::str(v.attr("__repr__")()));
		const std::string type = boost::python::extract<std::string>(v.attr("__class__").attr("__name__"));
		return repr + " (" + type + ")";
	}

	// A wrong type is a TypeError, as Python's own functions raise it (a wrong value stays a ValueError).
	[[noreturn]] inline void typeError(const std::string& message)
	{
		PyErr_SetString(PyExc_TypeError, message.c_str());
		boost::python::throw_error_already_set();
		throw std::logic_error("unreachable"); // throw_error_already_set does not return
	}

	// True is a number to Python; k1 = True is surely a slip, so it is refused as a number (numpy's
	// bool_ too). Other numbers, numpy's among them (float32, int64), are taken through float().
	inline double number(const char* name, const boost::python::object& v)
	{
		const std::string type = boost::python::extract<std::string>(v.attr("__class__").attr("__name__"));
		if (PyBool_Check(v.ptr()) || type == "bool_") typeError(std::string(name) + " = " + describe(v) + " is invalid: must be a number");
		boost::python::extract<double> x(v);
		if (x.check()) return x();
		if (PyIndex_Check(v.ptr()) || PyObject_HasAttrString(v.ptr(), "__float__")) {
			PyObject* f = PyNumber_Float(v.ptr());
			if (f) {
				const double d = PyFloat_AsDouble(f);
				Py_DECREF(f);
				return d;
			}
			PyErr_Clear();
		}
		typeError(std::string(name) + " = " + describe(v) + " is invalid: must be a number");
	}

	// A Python integer (not a bool, not a float) within [lo, hi]; `what` names the kind in the message.
	inline long integerIn(const char* name, const boost::python::object& v, const char* what, long lo, long hi)
	{
		if (PyBool_Check(v.ptr()) || !PyIndex_Check(v.ptr())) typeError(std::string(name) + " = " + describe(v) + " is invalid: must be " + what);
		PyObject* n = PyNumber_Index(v.ptr());
		if (!n) {
			PyErr_Clear();
			typeError(std::string(name) + " = " + describe(v) + " is invalid: must be " + what);
		}
		int        overflow = 0;
		const long x        = PyLong_AsLongAndOverflow(n, &overflow);
		Py_DECREF(n);
		if (overflow || x < lo || x > hi)
			throw std::invalid_argument(
			        std::string(name) + " = " + describe(v) + " is invalid: must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
		return x;
	}

	// A body id: a Python int in YADE's id range (an int), not a float or a bool.
	inline int id(const char* name, const boost::python::object& v)
	{
		return static_cast<int>(integerIn(name, v, "an integer body id", 0, std::numeric_limits<int>::max()));
	}

	// An object of class T (a shared_ptr<T> to Python), named in the error: e.g. a Material or an Interaction.
	template <class T> boost::shared_ptr<T> instance(const char* name, const boost::python::object& v, const char* what)
	{
		boost::python::extract<boost::shared_ptr<T>> x(v);
		if (v.is_none() || !x.check()) typeError(std::string(name) + " = " + describe(v) + " is invalid: must be " + what);
		return x();
	}

	inline std::string text(const char* name, const boost::python::object& v)
	{
		boost::python::extract<std::string> x(v);
		if (!PyUnicode_Check(v.ptr()) || !x.check()) typeError(std::string(name) + " = " + describe(v) + " is invalid: must be a string");
		return x();
	}

	inline bool flag(const char* name, const boost::python::object& v)
	{
		if (!PyBool_Check(v.ptr())) typeError(std::string(name) + " = " + describe(v) + " is invalid: must be True or False");
		return v.ptr() == Py_True;
	}

	// An int attribute (e.g. Material.id): a Python integer (not a bool) within C++'s int.
	inline int integer(const char* name, const boost::python::object& v)
	{
		return static_cast<int>(integerIn(name, v, "an integer", std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
	}

	inline void check(const char* name, Kind kind, const boost::python::object& v)
	{
		if (kind == Kind::Number) number(name, v);
		else if (kind == Kind::Text)
			text(name, v);
		else if (kind == Kind::Integer)
			integer(name, v);
		else
			flag(name, v);
	}

	struct Field {
		const char* name;
		Kind        kind;
	};

	// Checks the types of the constructor's keywords that are in fields (others are left to YADE);
	// numbers are handed on as Python floats, since YADE's own setters take no numpy scalar.
	template <std::size_t N> void checkKeywords(boost::python::dict& kw, const Field (&fields)[N])
	{
		for (const Field& f : fields)
			if (kw.has_key(f.name)) {
				check(f.name, f.kind, kw[f.name]);
				if (f.kind == Kind::Number) kw[f.name] = number(f.name, kw[f.name]);
			}
	}

	inline void replaceProperty(boost::python::object& cls, const char* name, const boost::python::object& get, const boost::python::object& set)
	{
		const boost::python::object doc = cls.attr(name).attr("__doc__");
		boost::python::setattr(cls, name, boost::python::import("builtins").attr("property")(get, set, boost::python::object(), doc));
	}

	template <class T> T convert(const char* name, const boost::python::object& v)
	{
		if constexpr (std::is_same_v<T, bool>) return flag(name, v);
		else if constexpr (std::is_same_v<T, std::string>)
			return text(name, v);
		else if constexpr (std::is_same_v<T, int>)
			return integer(name, v);
		else
			return static_cast<T>(number(name, v));
	}

	// The attribute of class C, set through a checked value; postLoad follows, as for YADE's
	// triggerPostLoad attributes (it validates the value and restores the old one if it is refused).
	template <class C, class T> void checked(boost::python::object& cls, const char* name, T C::*attr)
	{
		namespace bp = boost::python;
		auto get     = [attr](const C& c) { return c.*attr; };
		auto set     = [name, attr](C& c, const bp::object& v) {
                        c.*attr = convert<T>(name, v);
                        c.callPostLoad();
		};
		replaceProperty(
		        cls,
		        name,
		        bp::make_function(get, bp::default_call_policies(), boost::mpl::vector<T, const C&>()),
		        bp::make_function(set, bp::default_call_policies(), boost::mpl::vector<void, C&, const bp::object&>()));
	}

	// The same for a property with its own getter and setter.
	template <class C, class T> void checked(boost::python::object& cls, const char* name, T (C::*get)() const, void (C::*set)(T))
	{
		namespace bp = boost::python;
		auto setter  = [name, set](C& c, const bp::object& v) { (c.*set)(convert<T>(name, v)); };
		replaceProperty(
		        cls,
		        name,
		        bp::make_function(get),
		        bp::make_function(setter, bp::default_call_policies(), boost::mpl::vector<void, C&, const bp::object&>()));
	}

}
} // namespace yade::pychecks
