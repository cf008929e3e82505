// reduceComplex and morseComplex.
//
// An elimination of a pair (a, b), with a in the boundary of b by an invertible coefficient,
// leaves a complex with the same homology: the cells whose boundary held a get that of b
// subtracted, the cells whose boundary held b lose it. Coreductions (b bounded by a alone among
// the cells not set aside as critical) and collapses (a bounding b alone) change the other
// boundaries only by dropping cells, or by adding critical ones. So the boundary of any cell
// left, restricted to non-critical cells, stays that of the whole complex, and a chain of the
// small complex maps back by going over the eliminations in reverse: each adds the multiple of
// its upper cell that clears its lower cell from the boundary.
#include "mesh/homology/chain_reduction.h"

#include <algorithm>
#include <cstdlib>

namespace geomesh {

namespace {

std::span<const Incidence> downOf(const CellComplex& complex, CellId c, ComplexSide side) {
  return side == ComplexSide::Primal ? complex.faces(c) : complex.cofaces(c);
}

std::span<const Incidence> upOf(const CellComplex& complex, CellId c, ComplexSide side) {
  return side == ComplexSide::Primal ? complex.cofaces(c) : complex.faces(c);
}

class Reducer {
 public:
  Reducer(const CellComplex& complex, ComplexSide side) : complex_(complex), side_(side) {
    const std::size_t n = complex.size();
    alive_.assign(n, 1);
    critical_.assign(n, 0);
    openDown_.resize(n);
    aliveUp_.resize(n);
    level_.resize(n);
    for (CellId c = 0; c < n; ++c) {
      level_[c] = static_cast<std::int8_t>(levelOf(complex, c, side));
      openDown_[c] = static_cast<std::uint32_t>(down(c).size());
      aliveUp_[c] = static_cast<std::uint32_t>(up(c).size());
      noteOpenDown(c);
      if (aliveUp_[c] == 1) free_.push_back(c);
    }
    // Stacks pop the last first: reverse them so that the lowest numbered go first.
    for (auto& cells : empty_) std::reverse(cells.begin(), cells.end());
    std::reverse(free_.begin(), free_.end());
  }

  ComplexReduction run() {
    for (;;) {
      coreduceQueued();
      if (setAsideEmpty(0, 0) || collapseOne() || setAsideEmpty(1, 3)) continue;
      break;
    }
    result_.side = side_;
    for (CellId c = 0; c < alive_.size(); ++c)
      if (alive_[c]) result_.critical.push_back(c);
    return std::move(result_);
  }

 private:
  std::span<const Incidence> down(CellId c) const { return downOf(complex_, c, side_); }
  std::span<const Incidence> up(CellId c) const { return upOf(complex_, c, side_); }
  bool open(CellId c) const { return alive_[c] && !critical_[c]; }

  void noteOpenDown(CellId c) {
    if (openDown_[c] == 1) queue_.push_back(c);
    if (openDown_[c] == 0) empty_[level_[c]].push_back(c);
  }

  void remove(CellId c) {
    alive_[c] = 0;
    for (const Incidence& u : up(c))
      if (alive_[u.cell]) {
        --openDown_[u.cell];
        noteOpenDown(u.cell);
      }
    for (const Incidence& d : down(c))
      if (alive_[d.cell] && --aliveUp_[d.cell] == 1) free_.push_back(d.cell);
  }

  void eliminate(CellId lower, CellId upper, std::int32_t coefficient) {
    result_.pairs.push_back({lower, upper, coefficient});
    remove(lower);
    remove(upper);
  }

  void coreduceQueued() {
    while (head_ < queue_.size()) {
      const CellId b = queue_[head_++];
      if (!open(b) || openDown_[b] != 1) continue;
      for (const Incidence& a : down(b))
        if (open(a.cell)) {
          if (std::abs(a.sign) == 1) eliminate(a.cell, b, a.sign);
          break;
        }
    }
    queue_.clear();
    head_ = 0;
  }

  // Sets aside as critical one cell of a level in [from, to] whose boundary holds no open cell.
  bool setAsideEmpty(int from, int to) {
    for (int level = from; level <= to; ++level) {
      auto& cells = empty_[level];
      while (!cells.empty()) {
        const CellId c = cells.back();
        cells.pop_back();
        if (!open(c) || openDown_[c] != 0) continue;
        critical_[c] = 1;
        for (const Incidence& u : up(c))
          if (alive_[u.cell]) {
            --openDown_[u.cell];
            noteOpenDown(u.cell);
          }
        return true;
      }
    }
    return false;
  }

  bool collapseOne() {
    while (!free_.empty()) {
      const CellId a = free_.back();
      free_.pop_back();
      if (!open(a) || aliveUp_[a] != 1) continue;
      for (const Incidence& b : up(a))
        if (alive_[b.cell]) {
          if (critical_[b.cell] || std::abs(b.sign) != 1) break;
          eliminate(a, b.cell, b.sign);
          return true;
        }
    }
    return false;
  }

  const CellComplex& complex_;
  ComplexSide side_;
  std::vector<std::uint8_t> alive_, critical_;
  std::vector<std::uint32_t> openDown_, aliveUp_;
  std::vector<std::int8_t> level_;
  std::vector<CellId> queue_;
  std::size_t head_ = 0;
  std::array<std::vector<CellId>, 4> empty_;
  std::vector<CellId> free_;
  ComplexReduction result_;
};

// Maps critical cells back to chains of the whole complex, reusing dense scratch arrays.
class ChainLifter {
 public:
  ChainLifter(const CellComplex& complex, const ComplexReduction& reduction)
      : complex_(complex), reduction_(reduction), z_(complex.size(), 0), bd_(complex.size(), 0) {
    for (std::size_t i = 0; i < reduction.pairs.size(); ++i)
      pairsAt_[levelOf(complex, reduction.pairs[i].upper, reduction.side)].push_back(i);
  }

  // The chain `c` stands for; its boundary is left in boundaryOf().
  Chain lift(CellId c) {
    clear();
    add(c, 1);
    const auto& pairs = pairsAt_[levelOf(complex_, c, reduction_.side)];
    for (auto it = pairs.rbegin(); it != pairs.rend(); ++it) {
      const ReductionPair& p = reduction_.pairs[*it];
      if (const std::int64_t coefficient = bd_[p.lower]; coefficient != 0)
        add(p.upper, -coefficient * p.coefficient);
    }
    Chain chain;
    for (CellId x : touchedZ_)
      if (z_[x] != 0) chain.push_back({x, z_[x]});
    std::sort(chain.begin(), chain.end());
    chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
    return chain;
  }

  std::int64_t boundaryAt(CellId c) const { return bd_[c]; }

 private:
  void add(CellId x, std::int64_t m) {
    z_[x] += m;
    touchedZ_.push_back(x);
    for (const Incidence& f : downOf(complex_, x, reduction_.side)) {
      bd_[f.cell] += m * f.sign;
      touchedBd_.push_back(f.cell);
    }
  }

  void clear() {
    for (CellId x : touchedZ_) z_[x] = 0;
    for (CellId x : touchedBd_) bd_[x] = 0;
    touchedZ_.clear();
    touchedBd_.clear();
  }

  const CellComplex& complex_;
  const ComplexReduction& reduction_;
  std::array<std::vector<std::size_t>, 4> pairsAt_;
  std::vector<std::int64_t> z_, bd_;
  std::vector<CellId> touchedZ_, touchedBd_;
};

}  // namespace

ComplexReduction reduceComplex(const CellComplex& complex, ComplexSide side) {
  return Reducer(complex, side).run();
}

MorseComplex morseComplex(const CellComplex& complex, const ComplexReduction& reduction) {
  MorseComplex morse;
  for (CellId c : reduction.critical) morse.cells[levelOf(complex, c, reduction.side)].push_back(c);
  ChainLifter lifter(complex, reduction);
  for (int k = 0; k <= 3; ++k) {
    const auto& rows = k > 0 ? morse.cells[k - 1] : std::vector<CellId>{};
    morse.boundary[k].assign(rows.size(), std::vector<std::int64_t>(morse.cells[k].size(), 0));
    for (std::size_t j = 0; j < morse.cells[k].size(); ++j) {
      morse.chains[k].push_back(lifter.lift(morse.cells[k][j]));
      for (std::size_t i = 0; i < rows.size(); ++i)
        morse.boundary[k][i][j] = lifter.boundaryAt(rows[i]);
    }
  }
  return morse;
}

}  // namespace geomesh
