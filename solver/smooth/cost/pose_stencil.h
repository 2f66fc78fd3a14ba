// The call operators Ceres' AutoDiffCostFunction needs for a functor over
// 2, 3 or 4 consecutive pose blocks, forwarding to one
// `Evaluate(const T* const* poses, T* residuals)` of the derived functor, so
// that a stencil functor is written once for any width.
#ifndef TPOPT_SOLVER_POSE_STENCIL_H_
#define TPOPT_SOLVER_POSE_STENCIL_H_

namespace tpopt {

template <typename Derived>
class PoseStencil {
 public:
  template <typename T>
  bool operator()(const T* const p0, const T* const p1, T* r) const {
    const T* poses[] = {p0, p1};
    return Self().Evaluate(poses, r);
  }
  template <typename T>
  bool operator()(const T* const p0, const T* const p1, const T* const p2, T* r) const {
    const T* poses[] = {p0, p1, p2};
    return Self().Evaluate(poses, r);
  }
  template <typename T>
  bool operator()(const T* const p0, const T* const p1, const T* const p2, const T* const p3,
                  T* r) const {
    const T* poses[] = {p0, p1, p2, p3};
    return Self().Evaluate(poses, r);
  }

 private:
  const Derived& Self() const { return static_cast<const Derived&>(*this); }
};

}  // namespace tpopt

#endif  // TPOPT_SOLVER_POSE_STENCIL_H_
