#include "bench/bench.h"

#include <nlohmann/json.hpp>

namespace physdbg::bench {

nlohmann::json benchRecord(const std::string& name, long long n, double oursMs, const std::string& peer,
                           double peerMs) {
  nlohmann::json record;
  record["name"] = name;
  record["n"] = n;
  record["ours_ms"] = oursMs;
  if (peer.empty() || peerMs <= 0.0) {
    record["peer"] = nullptr;
    record["peer_ms"] = nullptr;
    record["ratio"] = nullptr;
  } else {
    record["peer"] = peer;
    record["peer_ms"] = peerMs;
    record["ratio"] = oursMs / peerMs;
  }
  return record;
}

}  // namespace physdbg::bench
