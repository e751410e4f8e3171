#include "Net/Private/TokenCheck.h"

namespace proxima::detail
{

bool tokenAccepted(const grpc::ServerContext& context, const std::string& token)
{
  return token.empty() || metadataEquals(context, kTokenMetadata, token);
}

bool metadataEquals(const grpc::ServerContext& context, const char* key,
                    const std::string& expected)
{
  const auto& metadata = context.client_metadata();
  const auto found = metadata.find(key);
  if (found == metadata.end() || found->second.size() != expected.size())
  {
    return false;
  }
  // Every character compared, whatever differs first: no timing hint of a partial match.
  unsigned difference = 0;
  for (std::size_t i = 0; i < expected.size(); ++i)
  {
    difference |=
      static_cast<unsigned char>(found->second.data()[i]) ^ static_cast<unsigned char>(expected[i]);
  }
  return difference == 0;
}

} // namespace proxima::detail
