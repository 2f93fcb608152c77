// What the SUNDIALS callbacks of KINSOL (kinsol_driver.cpp) and IDA (dae_ida.cpp) share: the
// exception guard that turns a throwing C++ body into SUNDIALS's return code — 0 success, >0
// recoverable (a parameterization refused the state: the solver backs off or cuts its step), <0
// fatal — so that no exception crosses the C boundary, and the copy of the assembled Eigen
// Jacobian into SUNDIALS's CSC matrix.
#pragma once

#include <sundials/sundials_types.h>
#include <sunmatrix/sunmatrix_sparse.h>

#include <exception>
#include <string>

#include "core/errors.hpp"
#include "core/nonlinear_system.hpp"

namespace rotbeam {

// `user` has `bool singular` and `std::string message`; `body()` returns the code on success.
template <class User, class Body>
int sundials_guard(User& user, const char* where, Body&& body) noexcept {
    try {
        return body();
    } catch (const SingularityError& e) {
        user.singular = true;  // near a singular angle: recoverable
        user.message = e.what();
        return 1;
    } catch (const std::exception& e) {
        user.message = e.what();
        return -1;
    } catch (...) {
        user.message = std::string("unknown exception in the ") + where;
        return -1;
    }
}

// Copies a compressed column-major matrix into a CSC SUNSparseMatrix allocated for its pattern
// (no allocation); −1 when the pattern has grown beyond the room SUNDIALS was given.
inline int copy_to_sunmatrix(const SparseMatrix& A, SUNMatrix J) {
    if (A.nonZeros() > SUNSparseMatrix_NNZ(J)) return -1;
    sunindextype* ptr = SUNSparseMatrix_IndexPointers(J);
    sunindextype* idx = SUNSparseMatrix_IndexValues(J);
    double* val = SUNSparseMatrix_Data(J);
    for (Eigen::Index c = 0; c <= A.outerSize(); ++c) ptr[c] = A.outerIndexPtr()[c];
    for (Eigen::Index k = 0; k < A.nonZeros(); ++k) {
        idx[k] = A.innerIndexPtr()[k];
        val[k] = A.valuePtr()[k];
    }
    return 0;
}

}  // namespace rotbeam
