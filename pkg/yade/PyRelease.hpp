// Objects assigned from Python (a phys, a geometry) hold their Python object: the last reference
// must go with the GIL held. YADE's engine threads run with the GIL released (O.run), so where the
// plugin drops such an object there, it hands it to the interpreter, which releases it in its own
// thread at its next chance.
#pragma once
#include <lib/base/Math.hpp>
#include <boost/python/converter/shared_ptr_deleter.hpp>
#include <Python.h>

namespace yade {
namespace pyrelease {

	// Whether Python owns this reference (boost::python made it from a Python object).
	template <class T> bool heldByPython(const shared_ptr<T>& p) { return boost::get_deleter<boost::python::converter::shared_ptr_deleter>(p) != nullptr; }

	template <class T> int releaseHeld(void* held)
	{
		delete static_cast<shared_ptr<T>*>(held);
		return 0;
	}

	// Empties p; its object is released by the interpreter (if its queue is full, it is kept, not
	// released unsafely).
	template <class T> void releaseInPython(shared_ptr<T>& p)
	{
		auto* held = new shared_ptr<T>(std::move(p));
		if (Py_AddPendingCall(releaseHeld<T>, held) != 0) { }
	}

	// p made empty and released safely where Python owns it; otherwise left to the caller.
	template <class T> void releaseIfHeld(shared_ptr<T>& p)
	{
		if (p && heldByPython(p)) releaseInPython(p);
	}

}
} // namespace yade::pyrelease
