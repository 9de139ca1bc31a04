// Python attributes whose wrong type is reported with the attribute's name. Boost.Python's own
// converters say only "Python argument types in None.None(MesoMat, str) did not match ...".
// The YADE-registered property is replaced by one that takes any object and checks it (its
// docstring is kept); constructors check their keywords the same way (checkKeywords).
#pragma once
#include <boost/python.hpp>
#include <boost/shared_ptr.hpp>
#include <climits>
#include <initializer_list>
#include <limits>
#include <vector>
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
				if (f.kind == Kind::Integer) kw[f.name] = integer(f.name, kw[f.name]); // a numpy integer as Python's
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

	// The type an attribute holds now (read back from Python), for one whose value comes unchecked:
	// a value of another type is refused naming the attribute, a numpy scalar taken as its Python type.
	inline boost::python::object typedLike(const char* name, const boost::python::object& current, const boost::python::object& v)
	{
		namespace bp = boost::python;
		if (PyBool_Check(current.ptr())) return bp::object(flag(name, v));
		if (PyLong_Check(current.ptr())) return bp::object(static_cast<long>(integerIn(name, v, "an integer", LONG_MIN, LONG_MAX)));
		if (PyFloat_Check(current.ptr())) return bp::object(number(name, v));
		if (PyUnicode_Check(current.ptr())) return bp::object(text(name, v));
		// a vector (Vector3, ...): a sequence of as many numbers, not a number, a string or a mapping
		const Py_ssize_t n = PyObject_HasAttrString(current.ptr(), "__len__") && !PyUnicode_Check(current.ptr()) ? PyObject_Length(current.ptr()) : -1;
		if (n < 0) PyErr_Clear();
		if (n > 0) {
			const bool       sequence = PySequence_Check(v.ptr()) && !PyUnicode_Check(v.ptr()) && !PyDict_Check(v.ptr());
			const Py_ssize_t m        = sequence ? PyObject_Length(v.ptr()) : -1;
			if (m < 0) PyErr_Clear();
			if (m != n) typeError(std::string(name) + " = " + describe(v) + " is invalid: must be a sequence of " + std::to_string(n) + " numbers");
			for (Py_ssize_t k = 0; k < n; ++k)
				number(name, bp::object(v[k]));
		}
		return v; // objects: YADE's converters name what they take
	}

	// A read-only property (YADE's Attr::readonly, a getter without setter) named, not Python's
	// "property of 'X' object has no setter".
	inline void refuseReadOnly(const boost::python::object& self, const std::string& name)
	{
		namespace bp           = boost::python;
		const bp::object descr = bp::object(self.attr("__class__").attr(name.c_str()));
		if (PyObject_IsInstance(descr.ptr(), reinterpret_cast<PyObject*>(&PyProperty_Type)) == 1 && bp::object(descr.attr("fset")).is_none()) {
			PyErr_SetString(
			        PyExc_AttributeError,
			        (name + " is read-only (" + bp::extract<std::string>(self.attr("__class__").attr("__name__"))() + " sets it)").c_str());
			bp::throw_error_already_set();
		}
	}

	inline std::string className(const boost::python::object& self) { return boost::python::extract<std::string>(self.attr("__class__").attr("__name__")); }

	// obj.name = v: an unknown name (a typo) is an AttributeError, not a new attribute nothing reads;
	// a value of the wrong type names the attribute.
	inline void setChecked(boost::python::object self, const boost::python::str& nameObj, const boost::python::object& v)
	{
		namespace bp            = boost::python;
		const std::string name  = bp::extract<std::string>(nameObj);
		const bp::object  klass = self.attr("__class__");
		if (!PyObject_HasAttrString(klass.ptr(), name.c_str())) {
			PyErr_SetString(
			        PyExc_AttributeError, (className(self) + " has no attribute '" + name + "' (a misspelt name would do nothing)").c_str());
			bp::throw_error_already_set();
		}
		refuseReadOnly(self, name);
		bp::object value = v;
		if (PyObject_HasAttrString(self.ptr(), name.c_str())) value = typedLike(name.c_str(), bp::object(self.attr(name.c_str())), v);
		bp::import("builtins").attr("object").attr("__setattr__")(self, nameObj, value);
	}

	// updateAttrs(d) all or nothing: every name known first, then set one by one (each checked as
	// above); a refused value puts back the ones already set.
	inline void updateAllOrNothing(boost::python::object self, const boost::python::dict& d)
	{
		namespace bp                   = boost::python;
		const bp::list           items = d.items();
		const bp::object         klass = self.attr("__class__");
		std::vector<std::string> names;
		for (bp::ssize_t k = 0; k < bp::len(items); ++k) {
			const std::string name = bp::extract<std::string>(bp::str(bp::object(items[k][0])));
			if (!PyObject_HasAttrString(klass.ptr(), name.c_str())) {
				PyErr_SetString(PyExc_AttributeError, (className(self) + " has no attribute '" + name + "': nothing was set").c_str());
				bp::throw_error_already_set();
			}
			refuseReadOnly(self, name);
			names.push_back(name);
		}
		bp::list old;
		for (const std::string& n : names)
			old.append(bp::object(self.attr(n.c_str())));
		bp::ssize_t set = 0;
		try {
			for (; set < bp::len(items); ++set)
				setChecked(self, bp::str(names[set]), bp::object(items[set][1]));
		} catch (...) {
			PyObject *type, *value, *trace; // the refusal is kept while the old values go back
			PyErr_Fetch(&type, &value, &trace);
			for (bp::ssize_t k = 0; k < set; ++k)
				bp::import("builtins").attr("object").attr("__setattr__")(self, bp::str(names[k]), bp::object(old[k]));
			PyErr_Restore(type, value, trace);
			throw;
		}
	}

	// Constructor keywords (before YADE applies them): unknown names and read-only attributes refused,
	// each value of the type the attribute holds (from the instance's own defaults, pyDict).
	template <class C> void ctorKeywords(const C& self, boost::python::dict& kw, std::initializer_list<const char*> readOnly = {})
	{
		namespace bp            = boost::python;
		const bp::dict defaults = self.pyDict();
		const bp::list keys     = kw.keys();
		for (bp::ssize_t k = 0; k < bp::len(keys); ++k) {
			const std::string name = bp::extract<std::string>(bp::str(bp::object(keys[k])));
			for (const char* r : readOnly)
				if (name == r) throw std::invalid_argument(name + " is read-only: the functor or engine sets it");
			if (!defaults.has_key(name)) continue; // YADE names an unknown keyword itself
			kw[name] = typedLike(name.c_str(), bp::object(defaults[name]), bp::object(kw[name]));
		}
	}

	// What every class of the plugin gets from Python (YADE's own classes accept a misspelt name and
	// set updateAttrs' keys before a bad one).
	inline void refuseUnknown(boost::python::object& cls) { boost::python::setattr(cls, "__setattr__", boost::python::make_function(&setChecked)); }

	inline void guard(boost::python::object& cls)
	{
		namespace bp = boost::python;
		refuseUnknown(cls);
		bp::setattr(cls, "updateAttrs", bp::make_function(&updateAllOrNothing, bp::default_call_policies(), (bp::arg("self"), bp::arg("attrs"))));
	}
}
} // namespace yade::pychecks
