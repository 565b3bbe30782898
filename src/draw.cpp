#include "contactfx/draw.h"

#include "contactfx/effects.h"

namespace cfx
{

SpriteLook LookOf(const ParticleTypeDef& type)
{
    if (type.streak > 0.0f)
    {
        return SpriteLook::spark;
    }
    if (type.sizeEnd > type.sizeStart || type.gravityScale <= 0.0f)
    {
        return SpriteLook::puff;
    }
    return SpriteLook::grain;
}

void CollectSprites(const Effects& effects, std::vector<ParticleSprite>& out)
{
    const ParticleView view = effects.Particles();
    const std::vector<ParticleTypeDef>& types = effects.Config().particleTypes;
    out.resize(view.count);
    for (std::uint32_t i = 0; i < view.count; ++i)
    {
        const std::uint32_t slot = view.Slot(i);
        const ParticleTypeDef& type = types[view.type[slot]];
        const ParticleLook look = LookAt(type, view.life[slot]);
        ParticleSprite& sprite = out[i];
        sprite.position = b2Vec2(view.positionX[slot], view.positionY[slot]);
        sprite.velocity = b2Vec2(view.velocityX[slot], view.velocityY[slot]);
        sprite.color = look.color;
        sprite.size = look.size;
        sprite.streak = type.streak;
        sprite.type = ParticleTypeId{view.type[slot]};
        sprite.look = LookOf(type);
        sprite.life = view.life[slot];
        sprite.lifetime = type.lifetime;
    }
}

} // namespace cfx
