#include "Net/Private/ModelOwnership.h"

#include "Net/Private/TokenCheck.h"

#include <cstdio>
#include <random>

namespace proxima::detail
{
namespace
{
// 128 random bits in hex: not guessable by another client on the same server.
std::string randomKey()
{
  std::random_device source;
  std::string key;
  for (int word = 0; word < 4; ++word)
  {
    char hex[9];
    std::snprintf(hex, sizeof hex, "%08x", static_cast<unsigned>(source()));
    key += hex;
  }
  return key;
}
} // namespace

std::string ModelOwnership::claim(const std::string& peer, std::string& holder)
{
  const std::lock_guard<std::mutex> lock(m_mutex);
  if (!m_key.empty())
  {
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - m_since).count();
    char since[64];
    std::snprintf(since, sizeof since, "%.1f s", seconds);
    holder = m_peer + ", for " + since;
    return {};
  }
  m_key = randomKey();
  m_peer = peer;
  m_since = std::chrono::steady_clock::now();
  return m_key;
}

void ModelOwnership::release(const std::string& key)
{
  const std::lock_guard<std::mutex> lock(m_mutex);
  if (m_key == key)
  {
    m_key.clear();
    m_peer.clear();
  }
}

ModelOwnership::Right ModelOwnership::mayChange(const grpc::ServerContext& context) const
{
  const bool carriesKey = context.client_metadata().count(kOwnerMetadata) > 0;
  const std::lock_guard<std::mutex> lock(m_mutex);
  if (!m_key.empty() && metadataEquals(context, kOwnerMetadata, m_key))
  {
    return Right::Granted;
  }
  if (carriesKey)
  {
    return Right::OwnershipEnded;
  }
  return m_key.empty() ? Right::Granted : Right::OwnedByAnother;
}

} // namespace proxima::detail
