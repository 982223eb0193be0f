#pragma once
/// \file
/// \brief Which features of two hulls produced an interference point (exact_contact.hpp);
/// reports carry it per point.

namespace grpvss::geometry {

/// \brief Which features produced an interference point. The order is the reports' order of
/// points at one place (it is also the alphabetical order of the printed names).
enum class InterferenceKind {
  kEdgeOfAOnFaceOfB,  ///< An edge of hull(A) meets a face of hull(B).
  kEdgeOfBOnFaceOfA,  ///< An edge of hull(B) meets a face of hull(A).
  kVertexOfAInB,      ///< A vertex of hull(A) lies in (closed) hull(B).
  kVertexOfBInA,      ///< A vertex of hull(B) lies in (closed) hull(A).
};

/// \brief Printable name of an InterferenceKind ("edge-of-A/face-of-B", ...).
const char* to_string(InterferenceKind kind);

}  // namespace grpvss::geometry
