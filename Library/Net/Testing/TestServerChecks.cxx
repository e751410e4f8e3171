// The server's two checks of a call, on contexts that carry the metadata a client would send
// (gRPC's ServerContextTestSpouse): the token, compared whole, and the model's ownership, one
// owner at a time with a key no other call can guess.
#include "Net/Private/ModelOwnership.h"
#include "Net/Private/TokenCheck.h"

#include <grpcpp/server_context.h>
#include <grpcpp/test/server_context_test_spouse.h>

#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <string>

namespace proxima::detail
{
namespace
{

// A call's context carrying `metadata` (key, value) pairs as a client's call would. The test
// spouse owns the strings the context's metadata points into, so it lives as long as the context.
class TestCall
{
public:
  explicit TestCall(std::initializer_list<std::pair<const char*, std::string>> metadata)
    : m_context(std::make_unique<grpc::ServerContext>())
    , m_spouse(std::make_unique<grpc::testing::ServerContextTestSpouse>(m_context.get()))
  {
    for (const auto& [key, value] : metadata)
    {
      m_spouse->AddClientMetadata(key, value);
    }
  }
  const grpc::ServerContext& operator*() const { return *m_context; }

private:
  std::unique_ptr<grpc::ServerContext> m_context;
  std::unique_ptr<grpc::testing::ServerContextTestSpouse> m_spouse;
};

TestCall callWith(std::initializer_list<std::pair<const char*, std::string>> metadata)
{
  return TestCall(metadata);
}

TEST(TokenCheck, NoTokenAskedAcceptsEveryCall)
{
  EXPECT_TRUE(tokenAccepted(*callWith({}), ""));
  EXPECT_TRUE(tokenAccepted(*callWith({{kTokenMetadata, "anything"}}), ""));
}

TEST(TokenCheck, ATokenIsAcceptedOnlyWhole)
{
  const std::string token = "s3cret-token";
  EXPECT_TRUE(tokenAccepted(*callWith({{kTokenMetadata, token}}), token));
  EXPECT_FALSE(tokenAccepted(*callWith({}), token));
  EXPECT_FALSE(tokenAccepted(*callWith({{kTokenMetadata, ""}}), token));
  EXPECT_FALSE(tokenAccepted(*callWith({{kTokenMetadata, "s3cret-toke"}}), token));
  EXPECT_FALSE(tokenAccepted(*callWith({{kTokenMetadata, token + "n"}}), token));
  EXPECT_FALSE(tokenAccepted(*callWith({{kTokenMetadata, "S3cret-token"}}), token));
  // Under another key it is not the token.
  EXPECT_FALSE(tokenAccepted(*callWith({{kOwnerMetadata, token}}), token));
}

TEST(ModelOwnership, OneOwnerAtATimeAndTheOthersAreToldWho)
{
  ModelOwnership ownership;
  std::string holder;
  const std::string key = ownership.claim("ipv4:10.0.0.5:4242", holder);
  ASSERT_FALSE(key.empty());
  EXPECT_TRUE(ownership.claim("ipv4:10.0.0.6:5151", holder).empty());
  EXPECT_EQ(holder.rfind("ipv4:10.0.0.5:4242, for ", 0), 0u) << holder;
  ownership.release("not the key");
  EXPECT_TRUE(ownership.claim("ipv4:10.0.0.6:5151", holder).empty()) << "a wrong key released it";
  ownership.release(key);
  const std::string next = ownership.claim("ipv4:10.0.0.6:5151", holder);
  ASSERT_FALSE(next.empty());
  EXPECT_NE(next, key);
}

TEST(ModelOwnership, OnlyTheOwnersKeyChangesTheModel)
{
  using Right = ModelOwnership::Right;
  ModelOwnership ownership;
  EXPECT_EQ(ownership.mayChange(*callWith({})), Right::Granted) << "nobody owns it";
  std::string holder;
  const std::string key = ownership.claim("peer", holder);
  EXPECT_EQ(ownership.mayChange(*callWith({})), Right::OwnedByAnother);
  EXPECT_EQ(ownership.mayChange(*callWith({{kOwnerMetadata, key}})), Right::Granted);
  EXPECT_EQ(ownership.mayChange(*callWith({{kOwnerMetadata, key.substr(1)}})),
            Right::OwnershipEnded);
  ownership.release(key);
  // A key that no longer owns is refused even with nobody owning: its client must learn that.
  EXPECT_EQ(ownership.mayChange(*callWith({{kOwnerMetadata, key}})), Right::OwnershipEnded);
  EXPECT_EQ(ownership.mayChange(*callWith({})), Right::Granted);
}

TEST(ModelOwnership, KeysDoNotRepeat)
{
  ModelOwnership ownership;
  std::set<std::string> keys;
  std::string holder;
  for (int i = 0; i < 200; ++i)
  {
    const std::string key = ownership.claim("peer", holder);
    ASSERT_GE(key.size(), 16u) << "a key short enough to guess";
    EXPECT_TRUE(keys.insert(key).second) << "key " << i << " repeated";
    ownership.release(key);
  }
}

} // namespace
} // namespace proxima::detail
